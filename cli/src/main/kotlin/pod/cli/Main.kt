package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.parse
import com.github.ajalt.clikt.core.subcommands
import com.github.ajalt.clikt.output.MordantHelpFormatter
import com.github.ajalt.clikt.parameters.options.versionOption
import pod.core.POD_VERSION
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.launch.Interruption
import pod.mavlink.link.LinkException
import kotlin.system.exitProcess

/** Where a command writes its lines; tests pass their own to read what a person would see. */
fun interface Output {
    fun line(text: String)
}

/** The `pod` command; [out] is standard output for people unless a caller (a test) reads the lines itself. */
class Pod(out: Output = TerminalOutput.standard()) : CliktCommand(name = "pod") {
    init {
        // Every option's help says its default; subcommands inherit the formatter from this context.
        configureContext { helpFormatter = { MordantHelpFormatter(it, showDefaultValues = true) } }
        versionOption(POD_VERSION, message = { "pod $it" })
        subcommands(listOf(SimCommand(out), WatchCommand(out), ReplayCommand(out), DemoCommand(out), MapCommand(out), SurveyCommand(out), RunCommand(), MissionGroup(out), ParamGroup(out), pod.cli.queue.QueueGroup(out), SigningGroup(out)) + actionCommands(out))
        subcommands(RouteCommand(out))
        subcommands(pod.cli.gcs.GcsCommand(out))
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

/**
 * Runs `pod` with [args] in this JVM as [main] does, without ending the process: help and results
 * go to [out], errors to [err] as one line each, and the exit code is returned ([Exit]). Nothing
 * escapes as an exception: a failure Pod did not foresee is one line and [Exit.FAILED], with the
 * stack trace only when [debug] (`POD_DEBUG=1`).
 */
fun run(
    args: List<String>,
    out: Output = TerminalOutput.standard(),
    err: Output = Output { System.err.println(it) },
    debug: Boolean = System.getenv("POD_DEBUG") == "1",
): Int {
    // With --json a script reads stdout: a bad input or an internal error is also an `error` event
    // there (a vehicle's refusal already is, from the command itself).
    val json = "--json" in args.takeWhile { it != "--" }
    var said: String? = null
    var internal = false
    val errLine = Output { line -> if (said == null) said = line; err.line(line) }
    val code = try {
        // The version leads a --json run's lines, before anything a command prints (Event.PodVersion).
        if (json) out.line(EventJson.encode(Event.PodVersion(POD_VERSION)))
        val pod = Pod(out)
        try {
            pod.parse(args)
            Exit.DONE
        } catch (e: CliktError) {
            ExitReport.of(pod, e, out, errLine)
        }
    } catch (e: Throwable) {
        internal = true
        ExitReport.internalError(e, errLine, debug)
    }
    val message = said
    if (json && message != null && (code == Exit.USAGE || internal)) {
        // The output may be what failed; the line on stderr has said it already.
        runCatching { out.line(EventJson.encode(Event.Error(message.removePrefix("error: ")))) }
    }
    return code
}

fun main(args: Array<String>) {
    Interruption.install({ System.err.println(it) })
    exitProcess(run(args.toList()))
}

/**
 * Lets this command read `-1` or `-8.59` as an argument. Clikt reads a token as a short option
 * when some option of the command has a one-dash name, and only `-h` has one in Pod; with help
 * as `--help` alone such tokens go to the arguments, while an unknown `--option` is still refused.
 * `-h` still shows the help: Clikt reads a token whose transformed form is a long option's name as
 * that option.
 */
internal fun CliktCommand.negativeNumbersAsArguments() = configureContext {
    helpOptionNames = setOf("--help")
    transformToken = { token -> if (token == "-h") "--help" else token }
}
