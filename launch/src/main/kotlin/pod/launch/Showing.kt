package pod.launch

import kotlinx.coroutines.CompletableDeferred
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
 * program's last event has been handed over, so callers see the whole run: everything up to the
 * engine's [EngineEvent.ProgramEnded] for this program, which itself is not handed over (nor are
 * the releases that follow it).
 */
public suspend fun <T> Engine.runShowing(
    names: (Int) -> String,
    onLine: (String) -> Unit = {},
    onEvent: (EngineEvent) -> Unit = {},
    block: suspend Program.() -> T,
): T = coroutineScope {
    val lines = EventLines(names)
    // The program's number is known once it starts; its events come after, so the collector waits for nothing.
    val program = CompletableDeferred<Int>()
    val shown = launch(start = CoroutineStart.UNDISPATCHED) {
        events.takeWhile { !(it is EngineEvent.ProgramEnded && it.program == program.await()) }.collect { event ->
            onEvent(event)
            lines.line(event)?.let(onLine)
        }
    }
    try {
        this@runShowing.run {
            program.complete(id)
            block()
        }
    } finally {
        // A bound, not a wait for time to pass: the program's end ends the collector.
        withTimeoutOrNull(5.seconds) { shown.join() }
        shown.cancel()
    }
}
