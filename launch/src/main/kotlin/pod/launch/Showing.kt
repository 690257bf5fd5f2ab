package pod.launch

import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.takeWhile
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.engine.Engine
import pod.core.engine.EngineEvent
import pod.core.engine.Program
import kotlin.time.Duration.Companion.seconds

/**
 * Runs [block] as a program on this engine, handing every event to [onEvent] and its line (see
 * [EventLines], vehicle names from [names]) to [onLine] as it happens. Returns only once the
 * program's last event has been handed over, so callers see the whole run.
 */
public suspend fun <T> Engine.runShowing(
    names: (Int) -> String,
    onLine: (String) -> Unit = {},
    onEvent: (EngineEvent) -> Unit = {},
    block: suspend Program.() -> T,
): T = coroutineScope {
    val lines = EventLines(names)
    val shown = launch(start = CoroutineStart.UNDISPATCHED) {
        events.takeWhile { !(it is EngineEvent.Message && it.text == END) }.collect { event ->
            onEvent(event)
            lines.line(event)?.let(onLine)
        }
    }
    try {
        this@runShowing.run {
            try {
                block()
            } finally {
                message(END)
            }
        }
    } finally {
        // A bound, not a wait for time to pass: the END marker ends the collector.
        withTimeoutOrNull(5.seconds) { shown.join() }
        shown.cancel()
    }
}

/** The last event of a program run by [runShowing]; never shown. */
private const val END = "\u0000end of program"
