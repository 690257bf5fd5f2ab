package pod.mavlink.command

import io.dronefleet.mavlink.common.CommandAck
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.buffer
import kotlinx.coroutines.flow.channelFlow
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import pod.mavlink.MavlinkVehicle
import pod.mavlink.Wire
import pod.mavlink.run
import kotlin.time.TimeSource

/**
 * Sends commands to one vehicle and waits for their answers (COMMAND_LONG / COMMAND_INT and
 * COMMAND_ACK).
 *
 * An acknowledgement names only the command, so two exchanges of the same MAV_CMD cannot be told
 * apart: those queue, while different commands run at once. [send] returns when the vehicle
 * accepted the command and throws [CommandRejected], [CommandTimeout] or
 * [pod.core.vehicle.VehicleLost] otherwise.
 */
public class CommandService internal constructor(
    private val vehicle: MavlinkVehicle,
    /** Timeouts of every command to this vehicle ([pod.mavlink.VehicleTiming.commands]). */
    public val timing: CommandTiming,
) {
    private val locks = HashMap<Int, Mutex>()

    /**
     * Sends [command] and suspends until the vehicle accepted it. Returns the vehicle's reply (its
     * `result_param2` means something for a few commands); [sending] does the same and reports
     * IN_PROGRESS percentages.
     */
    public suspend fun send(command: VehicleCommand): CommandReply =
        lockFor(command.command).withLock { exchange(command) {} }

    /**
     * [send] as a flow: collecting it sends [command]; each IN_PROGRESS answer is an element with
     * its percentage, and the last element carries the vehicle's final reply
     * ([CommandProgress.reply]). The flow throws what [send] throws.
     */
    public fun sending(command: VehicleCommand): Flow<CommandProgress> = channelFlow {
        var percent: Int? = null
        val reply = lockFor(command.command).withLock {
            exchange(command) {
                percent = it
                trySend(CommandProgress(it, null))
            }
        }
        send(CommandProgress(percent, reply))
    }.buffer(Channel.UNLIMITED)

    private fun lockFor(command: Int): Mutex = synchronized(locks) { locks.getOrPut(command) { Mutex() } }

    private suspend fun exchange(command: VehicleCommand, inProgress: (Int?) -> Unit): CommandReply {
        val identity = vehicle.identity.value
        val ourSystem = vehicle.station.config.systemId
        val realTime = vehicle.clock === TimeSource.Monotonic
        val machine = CommandTransaction(command, timing, vehicle.roundTrips.command, vehicle.lastHeartbeat.elapsedNow().inWholeNanoseconds)
        // Telemetry only tells that the vehicle is alive: forwarded at most every HEARD_EVERY.
        val heard = vehicle.clock.markNow()
        var heardForwarded = Long.MIN_VALUE / 4
        val wire = Wire<CommandInput, Int>(
            during = command.label,
            pick = { inbound ->
                val message = inbound.message
                when {
                    inbound.frame.componentId != identity.componentId -> null
                    // Older autopilots leave the target empty (0); anything else must be us.
                    message is CommandAck -> if (message.targetSystem().let { it == 0 || it == ourSystem }) {
                        CommandWire.reply(message)?.takeIf { it.command == command.command }?.let { CommandInput.Reply(it) }
                    } else {
                        null
                    }
                    else -> {
                        val now = heard.elapsedNow().inWholeNanoseconds
                        if (now - heardForwarded >= HEARD_EVERY_NANOS) {
                            heardForwarded = now
                            CommandInput.Heard
                        } else {
                            null
                        }
                    }
                }
            },
            encode = { confirmation ->
                if (command.frame == null) {
                    CommandWire.encodeLong(command, identity.systemId, identity.componentId, confirmation)
                } else {
                    CommandWire.encode(command, identity.systemId, identity.componentId, confirmation)
                }
            },
            giveUpAfter = timing.timeout,
            isAnswer = { it is CommandInput.Reply },
            // Texts come from the vehicle's joined STATUSTEXT lines (a long one arrives in chunks).
            texts = { line -> if (line.severity.ordinal <= MAV_SEVERITY_WARNING) CommandInput.Text(line.text) else null },
            // Polled on the real clock only: in virtual time an answer needs the scheduler to move on.
            hotWaitNanos = if (realTime) ({ vehicle.roundTrips.command.hotWaitNanos }) else ({ 0L }),
        )
        var reported = 0
        try {
            return vehicle.run(machine, wire) {
                // Each IN_PROGRESS the vehicle sends, even one without a percentage.
                if (machine.inProgressAnswers != reported) {
                    reported = machine.inProgressAnswers
                    inProgress(machine.progress)
                }
            }
        } catch (e: CommandRejected) {
            if (e.statusTexts.isNotEmpty()) throw e
            val t = vehicle.telemetry
            throw e.withHint(RefusalHints.forRefusal(command, e.result, vehicle.identity.value, t.mode.value?.name, t.armed.value))
        }
    }

    private companion object {
        /** Texts up to this severity explain a refusal; notices and info are chatter. */
        const val MAV_SEVERITY_WARNING = 4

        /** Least time between two "the vehicle is alive" notes to a command's machine. */
        const val HEARD_EVERY_NANOS = 100_000_000L
    }
}
