package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.vehicle.VehicleLost
import pod.launch.Interruption
import pod.launch.Interrupted
import pod.mavlink.GroundStation
import pod.mavlink.MavlinkVehicle
import pod.mavlink.action.ActionException
import pod.mavlink.command.CommandException
import pod.mavlink.mission.MissionException
import pod.mavlink.param.ParamException
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * A command that talks to one vehicle: opens the link, waits for the vehicle (`--sysid` picks one
 * when several answer), runs [act], and turns Pod's typed errors into a one-line message with exit
 * code 1 (and an `error` JSON line with `--json`).
 *
 * Ctrl-C or SIGTERM cancels [act] ([Interruption]); [afterInterrupt] then leaves the vehicle safe,
 * a line says how (an `interrupted` JSON object with `--json`) and the command exits with 130.
 */
internal abstract class VehicleCommandBase(protected val out: Output, name: String) : CliktCommand(name = name) {
    private val connect by option("--connect", help = "link to the vehicle (udpin:, udpout:, tcp:)").default("udpin:0.0.0.0:14550")
    private val sysid by option("--sysid", help = "the vehicle's system id (needed when several answer)").int().restrictTo(1..255)
    protected val json by option("--json", help = "JSON lines instead of text").flag()
    private val wait by option("--wait", help = "how long to wait for the vehicle's heartbeat")
        .convert { it.toDurationOrNull() ?: fail(NOT_A_DURATION.format(it)) }.default(10.seconds)

    /** Checks local inputs (files) before any link is opened. */
    protected open fun prepare() {}

    /** Does the work with the chosen vehicle. */
    protected abstract suspend fun act(vehicle: MavlinkVehicle)

    /**
     * Leaves [vehicle] safe after [act] was interrupted and says how ("holding in BRAKE"); throws
     * when it could not. This default leaves the vehicle as it is: right for commands that do not
     * fly it (a cancelled transfer ends itself). Commands that fly override it.
     */
    protected open suspend fun afterInterrupt(vehicle: MavlinkVehicle): String = "left as it was"

    override fun run() = runBlocking {
        prepare()
        val gcs = reportingLinkErrors { GroundStation.open(connect, this) }
        try {
            val vehicle = pick(gcs, wait)
            try {
                Interruption.cancellable { act(vehicle) }
            } catch (e: Interrupted) {
                stopped(vehicle, e.signal)
            } catch (e: MissionException) {
                fail(e.message ?: e.toString())
            } catch (e: CommandException) {
                fail(e.message ?: e.toString())
            } catch (e: ActionException) {
                fail(e.message ?: e.toString())
            } catch (e: ParamException) {
                fail(e.message ?: e.toString())
            } catch (e: VehicleLost) {
                fail(e.message ?: e.toString())
            }
        } finally {
            gcs.close()
        }
    }

    private suspend fun CoroutineScope.pick(gcs: GroundStation, wait: Duration): MavlinkVehicle {
        val wanted = sysid
        return try {
            withTimeout(wait) {
                if (wanted != null) {
                    gcs.vehicles.first { wanted in it }.getValue(wanted)
                } else {
                    val first = gcs.vehicles.first { it.isNotEmpty() }
                    // Give other vehicles on the link a moment to speak up before choosing.
                    kotlinx.coroutines.delay(1.5.seconds)
                    val all = gcs.vehicles.value
                    if (all.size > 1) fail("several vehicles answer (system ids ${all.keys.sorted().joinToString()}): pick one with --sysid")
                    first.values.first()
                }
            }
        } catch (e: TimeoutCancellationException) {
            fail(if (wanted != null) "no heartbeat from vehicle $wanted within $wait" else "no vehicle heard within $wait")
        }
    }

    private suspend fun stopped(vehicle: MavlinkVehicle, signal: String): Nothing {
        val outcome = withContext(NonCancellable) {
            withTimeoutOrNull(SAFE_TIMEOUT) { runCatching { afterInterrupt(vehicle) } }
                ?: Result.failure(IllegalStateException("no confirmation within $SAFE_TIMEOUT"))
        }
        val t = vehicle.telemetry
        val how = outcome.getOrElse { "NOT confirmed safe: ${it.message ?: it}" }
        out.line(
            if (json) {
                jsonLine(
                    "event" to "interrupted", "signal" to signal, "sysid" to vehicle.systemId, "safe" to outcome.isSuccess, "state" to how,
                    "mode" to t.mode.value?.name, "armed" to t.armed.value, "relative_alt_m" to t.position.value?.relativeAltitude?.meters,
                )
            } else {
                "interrupted by $signal: vehicle ${vehicle.systemId} $how (mode ${t.mode.value?.name ?: "unknown"}, ${if (t.armed.value) "armed" else "disarmed"})"
            },
        )
        throw CliktError("pod: stopped by $signal", statusCode = Interruption.EXIT_CODE)
    }

    protected fun fail(message: String): Nothing {
        if (json) out.line(jsonLine("event" to "error", "message" to message))
        throw CliktError("error: $message", statusCode = Exit.FAILED)
    }

    /** The closing line: [text] for people, a `done` JSON object with [json] fields for scripts. */
    protected fun finish(text: String, vararg json: Pair<String, Any?>) {
        out.line(if (this.json) jsonLine("event" to "done", *json) else text)
    }

    private companion object {
        /** How long an interrupted command waits for the vehicle to confirm it is safe. */
        val SAFE_TIMEOUT: Duration = 15.seconds
    }
}
