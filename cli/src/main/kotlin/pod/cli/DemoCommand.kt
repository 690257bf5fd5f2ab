package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.withTimeoutOrNull
import kotlinx.coroutines.delay
import pod.core.vehicle.Autopilot
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.VehicleType
import pod.mavlink.FleetEvent
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.seconds
import kotlin.time.Duration

/**
 * `pod demo`: the bundled scenario on loopback. Starts a ground station and simulated vehicles
 * (an ArduPilot quad, an ArduPilot plane, a PX4 quad, …), shows each as it connects with live
 * position, battery and mode, then stops one and shows it marked lost, and exits.
 */
internal class DemoCommand(private val out: Output) : CliktCommand(name = "demo") {
    private val count by option("--vehicles", help = "how many simulated vehicles").int().restrictTo(1..50).default(3)
    private val json by option("--json", help = "JSON lines instead of a table").flag()
    private val showFor by option("--show-for", help = "how long to show the full fleet before stopping a vehicle")
        .convert { text -> Duration.parseOrNull(text)?.takeUnless { it.isNegative() } ?: fail(NOT_A_DURATION.format(text)) }
        .default(3.seconds)

    override fun help(context: Context): String =
        "Simulated fleet on loopback: vehicles connect, show live telemetry, one is stopped and marked lost."

    override fun run() = runBlocking {
        val lostAfter = 3.seconds
        val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(lostAfter = lostAfter))
        val view = LiveView(out, json, period = 1.seconds, redraw = !json && System.console() != null)
        val vehicles = (1..count).map { id -> SimVehicle(demoVehicle(id, gcs.link.localPort)) }
        val shown = launch { view.show(gcs) }
        try {
            view.note("ground station listening on 127.0.0.1:${gcs.link.localPort}; starting $count simulated vehicles")
            vehicles.forEach { it.start(this) }
            step("every vehicle connected with a position", 20) {
                val fleet = gcs.vehicles.first { it.size == count }
                for (v in fleet.values) {
                    v.telemetry.position.filterNotNull().first()
                    v.telemetry.battery.filterNotNull().first()
                }
            }
            delay(showFor) // let people watch the live table for a moment
            val victim = vehicles.last()
            view.note("stopping vehicle ${victim.config.systemId}: it should be marked lost after ${lostAfter.inWholeSeconds} s of silence")
            val lost = launch(start = CoroutineStart.UNDISPATCHED) {
                gcs.events.filterIsInstance<FleetEvent.Lost>().first { it.vehicle.systemId == victim.config.systemId }
            }
            victim.stop()
            step("vehicle ${victim.config.systemId} marked lost", lostAfter.inWholeSeconds + 10) { lost.join() }
            val stillUp = gcs.vehicles.value.values.count { it.connection.value == ConnectionState.CONNECTED }
            view.note("done: $stillUp of $count vehicles connected, vehicle ${victim.config.systemId} lost")
            view.render(gcs)
            if (json) out.line(jsonLine("event" to "demo_done", "connected" to stillUp, "lost" to victim.config.systemId))
        } finally {
            shown.cancel()
            vehicles.forEach { it.stop() }
            gcs.close()
        }
    }

    private suspend fun CoroutineScope.step(what: String, seconds: Long, block: suspend () -> Unit) {
        try {
            withTimeout(seconds.seconds) { block() }
        } catch (e: TimeoutCancellationException) {
            throw CliktError("demo failed: no '$what' within $seconds s", statusCode = 1)
        }
    }

    private fun demoVehicle(id: Int, gcsPort: Int): SimVehicleConfig {
        val (type, autopilot) = when (id % 3) {
            1 -> VehicleType.QUADROTOR to Autopilot.ARDUPILOT
            2 -> VehicleType.FIXED_WING to Autopilot.ARDUPILOT
            else -> VehicleType.QUADROTOR to Autopilot.PX4
        }
        val base = SimVehicleConfig.DEFAULT_HOME
        return SimVehicleConfig(
            systemId = id,
            type = type,
            autopilot = autopilot,
            home = base.offset(north = pod.core.units.Distance(0.0), east = pod.core.units.Distance(15.0 * (id - 1))),
            gcs = "udpout://127.0.0.1:$gcsPort",
            initialCharge = 0.55 + 0.1 * (id % 4),
            timeScale = 60.0, // a minute of charging per second, so the battery column moves
        )
    }
}
