package pod.e2e

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.map
import kotlinx.serialization.SerializationException
import pod.cli.Output
import pod.cli.json.Event
import pod.cli.json.EventJson
import java.util.concurrent.CopyOnWriteArrayList

/**
 * What a `pod` command printed, line by line, and a flow to await a line as it comes. With
 * `--json`, read it through [events] / [eventFlow]: every line must then be one of the model's
 * events, and a line that is not fails the test with the line in the message.
 */
internal class Captured : Output {
    val lines = CopyOnWriteArrayList<String>()
    val flow = MutableSharedFlow<String>(replay = 10_000)

    override fun line(text: String) {
        lines += text
        flow.tryEmit(text)
    }

    /** Every line so far, decoded. */
    val events: List<Event> get() = lines.map(::decodeEvent)

    /** Every line as it comes, decoded (the lines before the one awaited are checked too). */
    val eventFlow: Flow<Event> get() = flow.map(::decodeEvent)

    /** The events of kind [E] as they come. */
    inline fun <reified E : Event> eventsOf(): Flow<E> = eventFlow.filterIsInstance<E>()
}

/** The tests that started as plain line collectors; the same class. */
internal typealias Lines = Captured

/** [line] as a `--json` event; fails the test when it is not one. */
internal fun decodeEvent(line: String): Event = try {
    EventJson.decode(line)
} catch (e: SerializationException) {
    throw AssertionError("not a pod --json event: $line (${e.message})", e)
}
