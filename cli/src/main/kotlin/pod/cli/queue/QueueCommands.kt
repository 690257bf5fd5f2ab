package pod.cli.queue

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.subcommands
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import pod.cli.Exit
import pod.cli.Output
import pod.cli.badInput
import pod.cli.json.Event
import pod.cli.json.EventJson

/** `pod queue`: a vehicle's dynamic mission queue, flown by `pod queue serve` and changed by the other subcommands. */
internal class QueueGroup(out: Output) : CliktCommand(name = "queue") {
    init {
        subcommands(
            listOf(QueueServe(out)) + Insertion.entries.map { InsertGroup(out, it) } +
                listOf(QueueNext(out), QueueClear(out), QueueStatusCommand(out)),
        )
    }

    override fun help(context: Context): String =
        "A vehicle's mission queue (Paparazzi's mission interface): `serve` flies it; append, prepend, replace, replace-all, next, clear and status change or show it."

    override fun run() = Unit
}

/**
 * A command that asks a running `pod queue serve` something ([QueueControlClient]) and prints the
 * answer. No host listening is exit 2, as a link that cannot be opened is for the other commands;
 * a host that fails or refuses the request is exit 1.
 */
internal abstract class QueueClientCommand(protected val out: Output, name: String) : CliktCommand(name = name) {
    private val control by option("--control", metavar = "HOST:PORT", help = "where `pod queue serve` takes requests")
        .convert { text ->
            try {
                ControlAddress.parse(text, anyPort = false)
            } catch (e: IllegalArgumentException) {
                this.fail(e.message ?: "bad address")
            }
        }.default(ControlAddress.DEFAULT, defaultForHelp = ControlAddress.DEFAULT.toString())
    protected val json by option("--json", help = "one JSON object instead of text").flag()

    /** The host's answer to [request]; ends the command when there is no host or it refused. */
    protected fun ask(request: QueueRequest): QueueResponse {
        val response = try {
            QueueControlClient(control).ask(request)
        } catch (e: NoQueueHost) {
            badInput(e.message ?: "no queue host on $control")
        } catch (e: QueueHostFailed) {
            failed(e.message ?: "the queue host on $control failed")
        }
        if (!response.ok) failed("the queue host refused: ${response.error}")
        return response
    }

    /**
     * Prints what the host did: for people, [text] and the queue; with --json, a `queue_done`
     * event naming [action].
     */
    protected fun report(action: String, text: String, response: QueueResponse) {
        val status = response.status ?: StatusJson(null, null, emptyList())
        val sysid = response.vehicle?.sysid ?: 0
        if (json) {
            return out.line(EventJson.encode(Event.QueueDone(action, sysid, response.entry, response.ended, status.current, status.remainingS, status.pending)))
        }
        out.line("vehicle $sysid: $text")
        out.line("queue ${contents(status)}")
    }

    private fun failed(message: String): Nothing {
        if (json) out.line(EventJson.encode(Event.Error(message)))
        throw CliktError("error: $message", statusCode = Exit.FAILED)
    }
}

/** `pod queue append|prepend|replace|replace-all PATTERN …`. */
internal class InsertGroup(out: Output, private val insertion: Insertion) : CliktCommand(name = insertion.command) {
    init {
        subcommands(patternCommands(out, insertion))
    }

    override fun help(context: Context): String = when (insertion) {
        Insertion.APPEND -> "Add an element at the end of the queue (it flies now when the queue is empty)."
        Insertion.PREPEND -> "Fly an element now, before the current one, which resumes after it."
        Insertion.REPLACE_CURRENT -> "Fly an element now instead of the current one, which is dropped."
        Insertion.REPLACE_ALL -> "Empty the queue and fly an element now."
    }

    override fun run() = Unit
}

/** `pod queue next`. */
internal class QueueNext(out: Output) : QueueClientCommand(out, "next") {
    override fun help(context: Context): String = "End the current element now; the next one flies (or the vehicle holds)."

    override fun run() {
        val response = ask(QueueRequest.Next)
        report("next", response.ended?.let { "ended ${it.describe()}" } ?: "the queue was empty: nothing to end", response)
    }
}

/** `pod queue clear`. */
internal class QueueClear(out: Output) : QueueClientCommand(out, "clear") {
    override fun help(context: Context): String = "Empty the queue; the vehicle holds where it is."

    override fun run() {
        report("clear", "cleared the queue: holding where it is", ask(QueueRequest.Clear))
    }
}

/** `pod queue status`. */
internal class QueueStatusCommand(out: Output) : QueueClientCommand(out, "status") {
    override fun help(context: Context): String = "Show the current element, its remaining time and the pending ones."

    override fun run() {
        val response = ask(QueueRequest.Status)
        val status = response.status ?: StatusJson(null, null, emptyList())
        val v = response.vehicle
        if (json) {
            return out.line(EventJson.encode(Event.QueueStatus(v?.sysid ?: 0, v?.mode, v?.armed, v?.relativeAltM, status.current, status.remainingS, status.pending)))
        }
        if (v != null) out.line("vehicle ${v.sysid}: ${v.mode ?: "mode unknown"}, ${if (v.armed) "armed" else "disarmed"}" + (v.relativeAltM?.let { ", %.1f m above home".format(it) } ?: ""))
        val current = status.current
        if (current == null) {
            out.line("queue empty: holding where it is")
            return
        }
        out.line("now:  ${current.describe()}" + (status.remainingS?.let { " (${it.toLong()} s left)" } ?: ""))
        status.pending.forEachIndexed { i, e -> out.line("${if (i == 0) "then:" else "     "} ${e.describe()}") }
    }
}

/** Ends a command on a bad element with the core's own message. */
internal inline fun <T> checkedElement(block: () -> T): T = try {
    block()
} catch (e: IllegalArgumentException) {
    badInput(e.message ?: "bad element")
}
