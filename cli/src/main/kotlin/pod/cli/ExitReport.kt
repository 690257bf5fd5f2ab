package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.MultiUsageError
import com.github.ajalt.clikt.core.PrintHelpMessage
import com.github.ajalt.clikt.core.UsageError
import com.github.ajalt.clikt.output.Localization
import com.github.ajalt.clikt.output.ParameterFormatter

/** How `pod` ends: what it prints for a [CliktError] or an unforeseen failure, and with which exit code. */
internal object ExitReport {
    /** Prints [e] the way a person should see it and returns its exit code. */
    fun of(pod: CliktCommand, e: CliktError, out: Output, err: Output): Int = when (e) {
        is PrintHelpMessage -> {
            pod.getFormattedHelp(e)?.let { (if (e.error) err else out).line(it) }
            if (e.error) Exit.USAGE else Exit.DONE
        }
        // Clikt gives its usage errors status 1; Pod keeps 1 for a vehicle that refused.
        is UsageError -> {
            err.line(usageLine(e))
            Exit.USAGE
        }
        else -> {
            e.message?.takeIf { it.isNotBlank() }?.let { (if (e.printError) err else out).line(it) }
            e.statusCode
        }
    }

    /** One line for an unexpected failure ([debug]: and its stack trace); [Exit.FAILED]. */
    fun internalError(e: Throwable, err: Output, debug: Boolean): Int {
        val what = e.message?.lineSequence()?.firstOrNull()?.takeIf { it.isNotBlank() }?.let { "${e.javaClass.simpleName}: $it" } ?: e.javaClass.name
        err.line("error: $what (internal error, please report it; POD_DEBUG=1 shows the stack trace)")
        if (debug) err.line(e.stackTraceToString().trimEnd())
        return Exit.FAILED
    }

    /** `error: no such option --frob (see 'pod arm --help')`: the message on one line, then where to look. */
    fun usageLine(e: UsageError): String {
        val errors = (e as? MultiUsageError)?.errors ?: listOf(e)
        val message = errors.joinToString("; ") { one ->
            val localization = one.context?.localization ?: ENGLISH
            one.formatMessage(localization, ParameterFormatter.Plain).lines().filter { it.isNotBlank() }.joinToString("; ")
        }
        val command = (errors.firstNotNullOfOrNull { it.context } ?: e.context)?.commandNameWithParents()?.joinToString(" ")
        return "error: $message" + (command?.let { " (see '$it --help')" } ?: "")
    }

    /** Clikt's own wording (every [Localization] member has its English default). */
    private val ENGLISH = object : Localization {}
}
