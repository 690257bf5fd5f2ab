package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.subcommands
import io.dronefleet.mavlink.common.CommandAck
import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.MavCmd
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeoutOrNull
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.VehicleCommand
import pod.mavlink.signing.LinkSigning
import pod.mavlink.signing.SigningClock
import pod.mavlink.signing.SigningKey
import pod.mavlink.signing.setupMessage
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** `pod signing …`: MAVLink 2 signing of a vehicle. */
internal class SigningGroup(out: Output) : CliktCommand(name = "signing") {
    init {
        subcommands(SigningSetup(out))
    }

    override fun help(context: Context): String = "Provision a vehicle with a MAVLink 2 signing key (SETUP_SIGNING)."

    override fun run() = Unit
}

/**
 * `pod signing setup --key-file K`: sends the key to the vehicle with SETUP_SIGNING over a link the
 * operator trusts (a cable, USB, a bench network: the key crosses it in the clear), then checks
 * what the vehicle does with it: it signs its own frames with the key, ignores an unsigned command
 * and answers a signed one.
 *
 * Until the vehicle holds the key the link accepts its unsigned frames; everything this command
 * sends is signed. ArduPilot refuses SETUP_SIGNING while armed, with "ERROR: Won't setup signing
 * when armed" (ArduPilot/ardupilot libraries/GCS_MAVLink/GCS_Signing.cpp, handle_setup_signing);
 * the command then fails naming that text.
 */
internal class SigningSetup(out: Output) : VehicleCommandBase(out, "setup") {
    override fun help(context: Context): String =
        "Send the signing key to the vehicle (SETUP_SIGNING, over a link you trust) and confirm it then refuses unsigned commands."

    override fun prepare() {
        if (signingKey(keyFile) == null) badInput("pod signing setup needs a key: --key-file K or \$POD_SIGNING_KEY")
    }

    override fun stationConfig(key: SigningKey?): GroundStationConfig =
        // Nothing asked of the vehicle but the probes, so that no other acknowledgement is taken for theirs.
        GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, signing = LinkSigning(requireNotNull(key), acceptUnsigned = true))

    override suspend fun act(vehicle: MavlinkVehicle) = coroutineScope {
        val key = requireNotNull(signingKey(keyFile))
        val signedFrame = async(start = CoroutineStart.UNDISPATCHED) { vehicle.messages.first { it.frame.signature != null } }
        vehicle.send(key.setupMessage(vehicle.systemId, vehicle.identity.value.componentId, SigningClock.fromEpochMillis(System.currentTimeMillis())))
        withTimeoutOrNull(SIGNS_WITHIN) { signedFrame.await() } ?: run {
            signedFrame.cancel()
            fail("vehicle ${vehicle.systemId} did not start signing within ${SIGNS_WITHIN.inWholeSeconds} s (armed? ArduPilot refuses SETUP_SIGNING while armed)")
        }
        if (answers(vehicle, signed = false)) fail("vehicle ${vehicle.systemId} signs now but still answered an unsigned command")
        if (!answers(vehicle, signed = true)) fail("vehicle ${vehicle.systemId} signs now but did not answer a signed command")
        finish("vehicle ${vehicle.systemId}: signing set up; it signs its frames, ignored an unsigned command and answered a signed one", vehicle, "signing-setup")
    }

    /** Whether [vehicle] acknowledges a harmless command (MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES) sent [signed] or not. */
    private suspend fun answers(vehicle: MavlinkVehicle, signed: Boolean): Boolean {
        if (signed) {
            return withTimeoutOrNull(ANSWER_WITHIN * 3) {
                try {
                    vehicle.commands.send(VehicleCommand(PROBE, param1 = 1f))
                } catch (e: CommandRejected) {
                    Unit // refused is an answer too
                }
                true
            } ?: false
        }
        return coroutineScope {
            val ack = async(start = CoroutineStart.UNDISPATCHED) {
                vehicle.messages.first { (it.message as? CommandAck)?.command()?.value() == PROBE }
            }
            val command = CommandLong.builder().targetSystem(vehicle.systemId).targetComponent(vehicle.identity.value.componentId)
                .command(MavCmd.MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES).param1(1f).build()
            station.link.sendToAll(FrameEncoder().encode(command, station.config.systemId, station.config.componentId, 0))
            val answered = withTimeoutOrNull(ANSWER_WITHIN) { ack.await() } != null
            ack.cancel()
            answered
        }
    }

    private companion object {
        /** MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES: harmless, and acknowledged by ArduPilot, PX4 and the simulator. */
        const val PROBE = 520
        val SIGNS_WITHIN: Duration = 5.seconds
        val ANSWER_WITHIN: Duration = 3.seconds
    }
}
