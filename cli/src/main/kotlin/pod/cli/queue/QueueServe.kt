package pod.cli.queue

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.double
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import pod.cli.Output
import pod.cli.VehicleCommandBase
import pod.cli.badInput
import pod.cli.json.Event
import pod.core.queue.MissionQueue
import pod.core.queue.QueueBusy
import pod.core.queue.WhenEmpty
import pod.core.units.m
import pod.mavlink.MavlinkVehicle
import pod.mavlink.queue.QueueElementRefused
import pod.mavlink.queue.QueueFlight
import pod.mavlink.queue.QueueNotFlyable
import java.io.IOException

/**
 * `pod queue serve`: holds a vehicle's mission queue and flies it ([QueueFlight], waiting when it
 * runs empty), taking the `pod queue` commands' requests on a loopback TCP endpoint
 * ([QueueControlServer]). The queue lives in this process, on the ground: it ends with it.
 *
 * Runs until Ctrl-C or SIGTERM, after which the vehicle holds where it is (as `pod run` and the
 * action commands leave it) and the command exits with 130. A vehicle that refuses an element, or
 * is lost, ends it with exit 1.
 */
internal class QueueServe(out: Output) : VehicleCommandBase(out, "serve") {
    private val control by option(
        "--control", metavar = "HOST:PORT",
        help = "loopback address to take `pod queue` requests on (127.0.0.1, ::1 or localhost; port 0: any free one, printed)",
    ).convert { text ->
        try {
            ControlAddress.parse(text, anyPort = true)
        } catch (e: IllegalArgumentException) {
            this.fail(e.message ?: "bad address")
        }
    }.default(ControlAddress.DEFAULT, defaultForHelp = ControlAddress.DEFAULT.toString())

    private val takeoff by option("--takeoff", metavar = "ALT", help = "when the vehicle is on the ground, take off to ALT metres above home first (switching to its take-off mode and arming as needed)")
        .convert {
            val a = it.toDoubleOrNull() ?: this.fail("not a number of metres: '$it'")
            if (!(a > 0 && a <= 10_000)) this.fail("the altitude must be above 0 m and at most 10000 m, was $it")
            a
        }

    private val timeScale by option(
        "--time-scale", metavar = "X",
        help = "vehicle seconds per real second, for a simulator running faster (pod sim --time-scale X): durations count in vehicle time",
    ).double().restrictTo(0.01..1000.0).default(1.0)

    override fun help(context: Context): String =
        "Fly a vehicle's mission queue and take `pod queue` commands for it (on 127.0.0.1:${QueueProtocol.DEFAULT_PORT} unless --control says otherwise), until interrupted."

    private var server: QueueControlServer? = null

    // The port is taken before the vehicle is looked for: one in use is bad input, said at once.
    override fun prepare() {
        val bound = try {
            QueueControlServer.bind(control)
        } catch (e: IllegalArgumentException) {
            badInput(e.message ?: "cannot listen on $control")
        }
        server = bound
        if (json) emit(Event.Listening(bound.address.toString(), bound.address.port)) else out.line("taking queue requests on ${bound.address}")
    }

    override fun run() {
        try {
            super.run()
        } finally {
            server?.close()
        }
    }

    override suspend fun afterInterrupt(vehicle: MavlinkVehicle): String = holdIfArmed(vehicle)

    override suspend fun act(vehicle: MavlinkVehicle): Unit = coroutineScope {
        val host = checkNotNull(server) { "prepare() binds the server" }
        // The vehicle's own queue, unless durations must count faster than the station's clock.
        val queue = if (timeScale == 1.0) vehicle.queue else MissionQueue(pod.core.time.Timebase.System, timeScale)
        val view = QueueView(out, json, vehicle, queue)
        launch {
            try {
                host.serve { answer(vehicle, queue, it) }
            } catch (e: IOException) {
                fail("the control endpoint on ${host.address} broke: ${e.message}")
            }
        }
        launch { view.follow() }
        try {
            takeOffIfAsked(vehicle, view)
            view.serving(host.address)
            QueueFlight(vehicle, queue).fly(WhenEmpty.WAIT)
        } catch (e: QueueNotFlyable) {
            fail(e.message + if (takeoff == null) "; or pass --takeoff ALT" else "")
        } catch (e: QueueElementRefused) {
            fail(e.message ?: e.toString())
        } catch (e: QueueBusy) {
            fail(e.message ?: e.toString())
        } finally {
            coroutineContext.cancelChildren()
            view.stop()
        }
    }

    private suspend fun takeOffIfAsked(vehicle: MavlinkVehicle, view: QueueView) {
        val height = takeoff ?: return
        if (vehicle.action.isFlying()) return
        view.note("vehicle ${vehicle.systemId}: on the ground: taking off to ${height.plain()} m")
        val changed = vehicle.action.getAirborne(height.m)
        view.note("vehicle ${vehicle.systemId}: ${changed.joinToString(", ")}")
    }

    /** What the host answers [request] with; called on the server's threads ([pod.core.queue.MissionQueue] is thread-safe). */
    private fun answer(vehicle: MavlinkVehicle, queue: MissionQueue, request: QueueRequest): QueueResponse {
        var entry: EntryJson? = null
        var ended: EntryJson? = null
        when (request) {
            is QueueRequest.Insert -> {
                val element = try {
                    request.element.toElement()
                } catch (e: IllegalArgumentException) {
                    return QueueResponse(ok = false, error = e.message)
                }
                entry = queue.insert(request.mode.mode, element).toJson()
            }
            QueueRequest.Next -> ended = queue.next()?.toJson()
            QueueRequest.Clear -> queue.clear()
            QueueRequest.Status -> Unit
        }
        val t = vehicle.telemetry
        val state = VehicleJson(vehicle.systemId, t.mode.value?.name, t.armed.value, t.position.value?.relativeAltitude?.meters)
        return QueueResponse(ok = true, entry = entry, ended = ended, status = queue.status.value.toJson(), vehicle = state)
    }
}
