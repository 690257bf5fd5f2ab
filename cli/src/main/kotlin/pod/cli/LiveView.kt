package pod.cli

import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.onSubscription
import kotlinx.coroutines.launch
import pod.cli.json.EventJson
import pod.cli.json.telemetryEvent
import pod.cli.json.toEvent
import pod.mavlink.FleetEvent
import pod.mavlink.GroundStation
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * Shows a ground station's fleet until cancelled: for people a table redrawn every [period] with
 * the latest events under it; with [json], one JSON object per event as it happens and one
 * telemetry object per vehicle every [period].
 */
internal class LiveView(
    private val out: Output,
    private val json: Boolean,
    private val period: Duration = 1.seconds,
    private val redraw: Boolean = System.console() != null,
) {
    private val recent = ArrayDeque<String>()

    suspend fun show(gcs: GroundStation): Nothing = coroutineScope {
        val announced = HashSet<Int>()
        launch {
            // Vehicles found before we subscribed are announced once, right after subscribing.
            gcs.events.onSubscription { gcs.vehicles.value.values.forEach { emit(FleetEvent.Found(it)) } }.collect { event ->
                if (event is FleetEvent.Found && !announced.add(event.vehicle.systemId)) return@collect
                if (json) {
                    out.line(EventJson.encode(event.toEvent()))
                } else {
                    val line = FleetView.eventLine(event)
                    if (redraw) remember(line) else out.line(line)
                }
            }
        }
        while (true) {
            delay(period)
            render(gcs)
        }
        @Suppress("UNREACHABLE_CODE")
        throw IllegalStateException()
    }

    fun render(gcs: GroundStation) {
        val vehicles = gcs.vehicles.value.values
        if (json) {
            vehicles.sortedBy { it.systemId }.forEach { out.line(EventJson.encode(telemetryEvent(it))) }
            return
        }
        val table = FleetView.table(vehicles)
        if (redraw) {
            out.line(CLEAR_SCREEN + (table + "" + recent).joinToString("\n"))
        } else {
            table.forEach(out::line)
            out.line("")
        }
    }

    fun note(text: String) {
        if (json) return
        if (redraw) remember(text) else out.line(text)
    }

    private fun remember(line: String) {
        recent.addLast(line)
        while (recent.size > 8) recent.removeFirst()
    }

    private companion object {
        const val CLEAR_SCREEN = "\u001b[H\u001b[2J"
    }
}
