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
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.core.vehicle.VehicleLost
import pod.launch.Interruption
import pod.launch.Interrupted
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.signing.SigningKey
import pod.mavlink.MavlinkVehicle
import pod.mavlink.action.ActionException
import pod.mavlink.command.CommandException
import pod.mavlink.mission.MissionException
import pod.mavlink.param.ParamException
import pod.mavlink.param.Parameter
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import pod.core.units.toReadable

/**
 * A command that talks to one vehicle: opens the link, waits for the vehicle (`--sysid` picks one
 * when several answer), runs [act], and turns Pod's typed errors into a one-line message with exit
 * code 1 (and an `error` JSON line with `--json`).
 *
 * Ctrl-C or SIGTERM cancels [act] ([Interruption]); [afterInterrupt] then leaves the vehicle safe,
 * a line says how (an `interrupted` JSON object with `--json`) and the command exits with 130.
 */
internal abstract class VehicleCommandBase(protected val out: Output, name: String) : CliktCommand(name = name) {
    private val connect by option("--connect", help = "link to the vehicle (udpin:, udpout:, tcp:, serial:///dev/ttyUSB0:57600)").default("udpin:0.0.0.0:14550")
    private val sysid by option("--sysid", help = "the vehicle's system id (needed when several answer)").int().restrictTo(1..255)
    protected val json by option("--json", help = "JSON lines instead of text").flag()
    protected val keyFile by keyFileOption()
    private val wait by option("--wait", help = "how long to wait for the vehicle's heartbeat ($DURATION_FORMAT)")
        .convert { it.toDurationOrNull() ?: fail(NOT_A_DURATION.format(it)) }.default(10.seconds)

    /** The station's configuration: signed with [key] (from `--key-file` or `$POD_SIGNING_KEY`) when there is one. */
    protected open fun stationConfig(key: SigningKey?): GroundStationConfig = signedConfig(key)

    /** The station [act] runs on (set before it runs). */
    protected lateinit var station: GroundStation

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

    /**
     * For [afterInterrupt] of commands that fly: an armed [vehicle] holds where it is
     * ([MavlinkVehicle.action]`.hold()`: a mode that keeps its height with nobody on the sticks).
     */
    protected suspend fun holdIfArmed(vehicle: MavlinkVehicle): String {
        val t = vehicle.telemetry
        if (!t.armed.value) return "is disarmed"
        vehicle.action.hold()
        return "holding in ${t.mode.value?.name}"
    }

    override fun run() = runBlocking {
        prepare()
        val gcs = reportingLinkErrors { GroundStation.open(connect, this, stationConfig(signingKey(keyFile))) }
        station = gcs
        try {
            val vehicle = pick(gcs, wait)
            val awaiting = launch { showAwaiting(vehicle) }
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
            } finally {
                awaiting.cancel()
            }
        } finally {
            // The next command may bind the same udpin port at once: release it before returning.
            withContext(NonCancellable) { gcs.closeAndAwait() }
        }
    }

    /**
     * The vehicle to talk to: the one with `--sysid`, else the only one heard. [wait] bounds the
     * wait for a heartbeat; once one vehicle is heard, others on the link get [OTHERS_WINDOW] (a
     * heartbeat period and a half) to speak up, outside [wait]. Says every few seconds what it
     * waits for and whom it heard.
     */
    private suspend fun CoroutineScope.pick(gcs: GroundStation, wait: Duration): MavlinkVehicle {
        val wanted = sysid
        fun heard() = gcs.vehicles.value.keys.sorted()
        val progress = launch {
            val started = TimeSource.Monotonic.markNow()
            while (true) {
                delay(WAITING_EVERY)
                val heard = heard()
                // Once the vehicle asked for is heard, the pick is only giving others a moment.
                if (if (wanted == null) heard.isNotEmpty() else wanted in heard) continue
                val waited = started.elapsedNow().toReadable()
                out.line(
                    if (json) {
                        EventJson.encode(Event.Waiting(wanted, "heartbeat", heard = heard, waitedS = started.elapsedNow().inWholeMilliseconds / 1000.0, timeoutS = wait.inWholeMilliseconds / 1000.0))
                    } else {
                        "waiting for ${wanted?.let { "vehicle $it" } ?: "a vehicle"} (${waited} of ${wait.toReadable()}) — " +
                            if (heard.isEmpty()) "none heard yet" else "heard ${heard.joinToString()}"
                    },
                )
            }
        }
        try {
            if (wanted != null) {
                return withTimeoutOrNull(wait) { gcs.vehicles.first { wanted in it }.getValue(wanted) }
                    ?: fail("no heartbeat from vehicle $wanted within ${wait.toReadable()}" + heard().let { if (it.isEmpty()) "; no vehicle heard at all" else "; heard ${it.joinToString()}" })
            }
            withTimeoutOrNull(wait) { gcs.vehicles.first { it.isNotEmpty() } } ?: fail("no vehicle heard within ${wait.toReadable()}")
            withTimeoutOrNull(OTHERS_WINDOW) { gcs.vehicles.first { it.size > 1 } }
            val all = gcs.vehicles.value
            if (all.size > 1) fail("several vehicles answer (system ids ${all.keys.sorted().joinToString()}): pick one with --sysid")
            return all.values.first()
        } finally {
            progress.cancel()
        }
    }

    /** Says what [vehicle] leaves unanswered while it lasts, at most every [WAITING_EVERY] for the same exchange. */
    private suspend fun showAwaiting(vehicle: MavlinkVehicle) {
        var lastWhat: String? = null
        var lastShown = TimeSource.Monotonic.markNow()
        vehicle.awaiting.filterNotNull().collect { a ->
            if (a.what == lastWhat && lastShown.elapsedNow() < WAITING_EVERY) return@collect
            lastWhat = a.what
            lastShown = TimeSource.Monotonic.markNow()
            out.line(
                if (json) {
                    EventJson.encode(
                        Event.Waiting(
                            a.systemId, a.what, attempt = a.attempt,
                            waitedS = a.waited.inWholeMilliseconds / 1000.0, timeoutS = a.giveUpAfter?.let { it.inWholeMilliseconds / 1000.0 },
                        ),
                    )
                } else {
                    a.describe()
                },
            )
        }
    }

    private suspend fun stopped(vehicle: MavlinkVehicle, signal: String): Nothing {
        val outcome = withContext(NonCancellable) {
            withTimeoutOrNull(SAFE_TIMEOUT) { runCatching { afterInterrupt(vehicle) } }
                ?: Result.failure(IllegalStateException("no confirmation within ${SAFE_TIMEOUT.toReadable()}"))
        }
        val t = vehicle.telemetry
        val how = outcome.getOrElse { "NOT confirmed safe: ${it.message ?: it}" }
        if (json) {
            emit(
                Event.Interrupted(
                    signal = signal, sysid = vehicle.systemId, safe = outcome.isSuccess, state = how,
                    mode = t.mode.value?.name, armed = t.armed.value, relativeAltM = t.position.value?.relativeAltitude?.meters,
                ),
            )
        } else {
            out.line("interrupted by $signal: vehicle ${vehicle.systemId} $how (mode ${t.mode.value?.name ?: "unknown"}, ${if (t.armed.value) "armed" else "disarmed"})")
        }
        throw CliktError("pod: stopped by $signal", statusCode = Interruption.EXIT_CODE)
    }

    protected fun fail(message: String): Nothing {
        if (json) emit(Event.Error(message))
        throw CliktError("error: $message", statusCode = Exit.FAILED)
    }

    /** Prints [event] as a JSON line (callers print it only with `--json`). */
    protected fun emit(event: Event) {
        out.line(EventJson.encode(event))
    }

    /**
     * The closing line: [text] for people; for scripts a `done` event naming [action], with
     * [vehicle]'s mode, armed state and altitude as the command ends, and what the command
     * concerned: the list's [items], the [param] read or written.
     */
    protected fun finish(text: String, vehicle: MavlinkVehicle, action: String, items: Int? = null, param: Parameter? = null, requested: Double? = null) {
        if (!json) return out.line(text)
        val t = vehicle.telemetry
        emit(
            Event.Done(
                action = action, sysid = vehicle.systemId, mode = t.mode.value?.name, armed = t.armed.value,
                relativeAltM = t.position.value?.relativeAltitude?.meters,
                items = items, name = param?.name, value = param?.value, type = param?.type?.name, requested = requested,
            ),
        )
    }

    private companion object {
        /** How long an interrupted command waits for the vehicle to confirm it is safe. */
        val SAFE_TIMEOUT: Duration = 15.seconds

        /** After the first vehicle is heard, how long others get to speak up: a heartbeat period (1 s) and a half. */
        val OTHERS_WINDOW: Duration = 1.5.seconds

        /** How often a wait is reported while it lasts. */
        val WAITING_EVERY: Duration = 2.seconds
    }
}
