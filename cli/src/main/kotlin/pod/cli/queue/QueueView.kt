package pod.cli.queue

import com.github.ajalt.mordant.animation.Animation
import com.github.ajalt.mordant.animation.animation
import com.github.ajalt.mordant.rendering.TextColors
import com.github.ajalt.mordant.rendering.TextStyles
import com.github.ajalt.mordant.rendering.Widget
import com.github.ajalt.mordant.table.table
import com.github.ajalt.mordant.table.verticalLayout
import com.github.ajalt.mordant.widgets.Text
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import pod.cli.Output
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.cli.liveTerminal
import pod.core.queue.EndReason
import pod.core.queue.QueueEvent
import pod.core.queue.QueueStatus
import pod.core.queue.MissionQueue
import pod.mavlink.MavlinkVehicle
import kotlin.time.Duration.Companion.seconds

/**
 * What `pod queue serve` shows of the queue it flies, until cancelled.
 *
 * At an interactive terminal a Mordant animation redraws, in place, the vehicle's state, the
 * current element with its remaining time and the pending ones, with the latest events under
 * them. Elsewhere (a pipe, a file, the tests' [Output]) a line per event and a line whenever the
 * queue's contents change. With [json], a `queue_started`, `queue_ended` or `queue_emptied` line
 * per event and a `queue_status` line per status change.
 */
internal class QueueView(private val out: Output, private val json: Boolean, private val vehicle: MavlinkVehicle, private val queue: MissionQueue) {
    private val animation: Animation<Widget>? = out.liveTerminal?.takeIf { !json }?.animation { it }
    private val recent = ArrayDeque<String>()
    private var header = "vehicle ${vehicle.systemId}"

    /** Shows the queue's events and status until cancelled. */
    suspend fun follow(): Nothing = coroutineScope {
        launch { queue.events.collect(::show) }
        launch {
            // An empty queue at the start goes without saying.
            var shownIds: List<Long> = emptyList()
            queue.status.collect { status ->
                val ids = listOfNotNull(status.current?.id) + status.pending.map { it.id }
                when {
                    json -> out.line(EventJson.encode(statusEvent(vehicle, status)))
                    animation != null -> redraw()
                    ids != shownIds -> out.line("vehicle ${vehicle.systemId}: queue ${contents(status.toJson())}")
                }
                shownIds = ids
            }
        }
        while (true) {
            delay(1.seconds)
            if (animation != null) redraw()
        }
        @Suppress("UNREACHABLE_CODE")
        error("unreachable")
    }

    /** Says something for people (a line, or under the live view); nothing with --json. */
    @Synchronized
    fun note(text: String) {
        if (json) return
        if (animation == null) return out.line(text)
        recent.addLast(text)
        while (recent.size > RECENT) recent.removeFirst()
        redraw()
    }

    /** The flight began: requests are taken on [control]. */
    fun serving(control: ControlAddress) {
        header = "vehicle ${vehicle.systemId} · requests on $control"
        val t = vehicle.telemetry
        if (json) {
            out.line(EventJson.encode(Event.QueueServing(vehicle.systemId, control.toString(), t.mode.value?.name, t.position.value?.relativeAltitude?.meters)))
        } else {
            note("vehicle ${vehicle.systemId}: flying its queue (${state()}); `pod queue append|prepend|replace|replace-all|next|clear|status --control $control` change it")
        }
    }

    /** Leaves the last frame on screen: what is printed next goes under it. */
    @Synchronized
    fun stop() {
        animation?.stop()
    }

    private fun show(event: QueueEvent) {
        val id = vehicle.systemId
        if (json) {
            return out.line(EventJson.encode(pod.cli.json.queueEvent(id, event)))
        }
        note(
            when (event) {
                is QueueEvent.Started -> "vehicle $id: flying ${event.entry.toJson().describe()}"
                is QueueEvent.Ended -> "vehicle $id: #${event.entry.id} ${ENDED.getValue(event.reason)}"
                is QueueEvent.Emptied -> "vehicle $id: the queue is empty: holding where it is (${state()})"
            },
        )
    }

    @Synchronized
    private fun redraw() {
        val live = animation ?: return
        val status = queue.status.value.toJson()
        live.update(
            verticalLayout {
                cell(TextStyles.bold("$header · ${state()}"))
                cell(
                    table {
                        header { row("", "#", "element", "left") }
                        body {
                            val current = status.current
                            if (current == null) row(TextColors.yellow("now"), "", "empty: holding", "")
                            else row(TextColors.green("now"), current.id, current.element.describe(), status.remainingS?.let { "${it.toLong()} s" } ?: "")
                            status.pending.forEachIndexed { i, e -> row(if (i == 0) "then" else "", e.id, e.element.describe(), "") }
                        }
                    },
                )
                recent.forEach { cell(Text(it)) }
            },
        )
    }

    private fun state(): String {
        val t = vehicle.telemetry
        val height = t.position.value?.relativeAltitude?.meters?.let { "%.1f m".format(it) } ?: "height unknown"
        return "${t.mode.value?.name ?: "mode unknown"}, ${if (t.armed.value) "armed" else "disarmed"}, $height"
    }

    private companion object {
        const val RECENT = 6

        val ENDED = mapOf(
            EndReason.ARRIVED to "done: arrived",
            EndReason.ELAPSED to "done: its time ran out",
            EndReason.SKIPPED to "ended by next",
            EndReason.PREEMPTED to "paused: a prepended element goes first",
            EndReason.REPLACED to "replaced",
            EndReason.CLEARED to "dropped: the queue was cleared",
        )
    }
}

/** "now #1 goto (30 N, 0 E) (12 s left); then #2 …, #3 …", or "empty". */
internal fun contents(status: StatusJson): String {
    val current = status.current ?: return "empty"
    val left = status.remainingS?.let { " (${it.toLong()} s left)" }.orEmpty()
    val then = if (status.pending.isEmpty()) "" else "; then " + status.pending.joinToString(", ") { it.describe() }
    return "now ${current.describe()}$left$then"
}

/** The `queue_status` event of [vehicle] with [status]. */
internal fun statusEvent(vehicle: MavlinkVehicle, status: QueueStatus): Event.QueueStatus {
    val t = vehicle.telemetry
    val s = status.toJson()
    return Event.QueueStatus(vehicle.systemId, t.mode.value?.name, t.armed.value, t.position.value?.relativeAltitude?.meters, s.current, s.remainingS, s.pending)
}
