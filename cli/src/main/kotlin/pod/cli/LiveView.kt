package pod.cli

import com.github.ajalt.mordant.animation.Animation
import com.github.ajalt.mordant.animation.animation
import com.github.ajalt.mordant.rendering.TextStyle
import com.github.ajalt.mordant.rendering.Widget
import com.github.ajalt.mordant.table.verticalLayout
import com.github.ajalt.mordant.widgets.Text
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.onSubscription
import kotlinx.coroutines.launch
import pod.cli.json.EventJson
import pod.cli.json.radioEvent
import pod.cli.json.telemetryEvent
import pod.mavlink.radio.RadioStatus
import pod.cli.json.toEvent
import pod.mavlink.FleetEvent
import pod.mavlink.GroundStation
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * Shows a ground station's fleet until cancelled.
 *
 * At an interactive terminal ([Output.liveTerminal]) a Mordant animation redraws the fleet table in
 * place every [period], in colour, with the latest events under it. Anywhere else (a pipe, a file,
 * the tests' [Output]) the table is printed as plain lines every [period] and each event as a line
 * when it happens. With [json], one JSON object per event as it happens and one telemetry object
 * per vehicle every [period].
 */
internal class LiveView(
    private val out: Output,
    private val json: Boolean,
    private val period: Duration = 1.seconds,
) {
    private val animation: Animation<Widget>? = out.liveTerminal?.takeIf { !json }?.animation { it }
    private val recent = ArrayDeque<Pair<String, TextStyle?>>()
    private var rows: List<VehicleRow> = emptyList()
    private var radio: RadioStatus? = null

    /** Shows [gcs] until cancelled; [subscribed] completes once its fleet events are watched (none is missed after). */
    suspend fun show(gcs: GroundStation, subscribed: CompletableDeferred<Unit>? = null): Nothing = coroutineScope {
        val announced = HashSet<Int>()
        launch {
            // Vehicles found before we subscribed are announced once, right after subscribing.
            gcs.events.onSubscription {
                gcs.vehicles.value.values.forEach { emit(FleetEvent.Found(it)) }
                subscribed?.complete(Unit)
            }.collect { event ->
                if (event is FleetEvent.Found && !announced.add(event.vehicle.systemId)) return@collect
                if (json) out.line(EventJson.encode(event.toEvent())) else note(FleetView.eventLine(event), FleetView.eventStyle(event))
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
        val vehicles = gcs.vehicles.value.values.sortedBy { it.systemId }
        val radio = gcs.radio.value
        if (json) {
            vehicles.forEach { out.line(EventJson.encode(telemetryEvent(it))) }
            radio?.let { out.line(EventJson.encode(radioEvent(it))) }
        } else {
            draw(vehicles.map(FleetView::row), radio)
        }
    }

    /** Shows the table of [rows]: redrawn in place at a terminal, printed as plain lines elsewhere. */
    @Synchronized
    fun draw(rows: List<VehicleRow>, radio: RadioStatus? = null) {
        this.rows = rows
        this.radio = radio
        val live = animation
        if (live != null) {
            live.update(frame())
        } else {
            FleetView.plainLines(FleetView.table(rows)).forEach(out::line)
            radio?.let { out.line(FleetView.radioLine(it)) }
            out.line("")
        }
    }

    /** Says [text] for people: under the live table at a terminal, as its own line elsewhere; nothing with --json. */
    @Synchronized
    fun note(text: String, style: TextStyle? = null) {
        if (json) return
        val live = animation
        if (live == null) {
            out.line(text)
            return
        }
        recent.addLast(text to style)
        while (recent.size > RECENT_EVENTS) recent.removeFirst()
        live.update(frame())
    }

    /** Draws [gcs]'s fleet a last time and [stop]s. */
    @Synchronized
    fun finish(gcs: GroundStation) {
        render(gcs)
        stop()
    }

    /** Leaves the last frame on screen: what is printed next goes under it, not above a redrawn table. */
    @Synchronized
    fun stop() {
        animation?.stop()
    }

    private fun frame(): Widget = verticalLayout {
        cell(FleetView.table(rows))
        radio?.let { cell(Text(FleetView.radioStyle(it)(FleetView.radioLine(it)))) }
        cell("")
        recent.forEach { (text, style) -> cell(Text(style?.invoke(text) ?: text)) }
    }

    private companion object {
        /** How many of the latest events show under the live table. */
        const val RECENT_EVENTS = 8
    }
}
