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

/** The `pod` command. */
class Pod(out: Output = Output { println(it) }) : CliktCommand(name = "pod") {
    init {
        subcommands(listOf(SimCommand(out), WatchCommand(out), DemoCommand(out), RunCommand(), MissionGroup(out), ParamGroup(out)) + actionCommands(out))
    }

    override fun help(context: Context): String = "Program fleets of drones over MAVLink."

    override fun run() = Unit
}

/** Runs [block], turning link errors into a one-line message and exit code 2. */
internal inline fun <T> reportingLinkErrors(block: () -> T): T = try {
    block()
} catch (e: LinkException) {
    throw CliktError("error: ${e.message}", statusCode = 2)
}

fun main(args: Array<String>) {
    Interruption.install({ System.err.println(it) })
    Pod().main(args)
}
