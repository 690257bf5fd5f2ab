package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.main
import com.github.ajalt.clikt.core.subcommands
import pod.launch.Interruption
import pod.mavlink.link.LinkException

/** Where a command writes its lines; tests pass their own to read what a person would see. */
fun interface Output {
    fun line(text: String)
}

/** The `pod` command; [out] is standard output for people unless a caller (a test) reads the lines itself. */
class Pod(out: Output = TerminalOutput.standard()) : CliktCommand(name = "pod") {
    init {
        subcommands(listOf(SimCommand(out), WatchCommand(out), DemoCommand(out), RunCommand(), MissionGroup(out), ParamGroup(out)) + actionCommands(out))
    }

    override fun help(context: Context): String = "Program fleets of drones over MAVLink."

    override fun run() = Unit
}

/** The exit codes of every `pod` command (the README's "Exit codes" lists them). */
internal object Exit {
    /** Done as asked. */
    const val DONE = 0

    /** The vehicle refused or failed (a command denied, a transfer that did not complete, a lost vehicle). */
    const val FAILED = 1

    /** Bad usage or input: an unknown option, a malformed argument or file, a link address that cannot be opened. */
    const val USAGE = 2

    /** Stopped by Ctrl-C or SIGTERM ([Interruption.EXIT_CODE]). */
    const val INTERRUPTED = Interruption.EXIT_CODE
}

/** Ends the command with a one-line message naming the bad input and [Exit.USAGE]. */
internal fun badInput(message: String): Nothing = throw CliktError("error: $message", statusCode = Exit.USAGE)

/** Runs [block], turning link errors into a one-line message and [Exit.USAGE]. */
internal inline fun <T> reportingLinkErrors(block: () -> T): T = try {
    block()
} catch (e: LinkException) {
    throw CliktError("error: ${e.message}", statusCode = Exit.USAGE)
}

fun main(args: Array<String>) {
    Interruption.install({ System.err.println(it) })
    Pod().main(args)
}
