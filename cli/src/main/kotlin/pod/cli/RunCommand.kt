package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.UsageError
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.double
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.restrictTo
import pod.cli.script.ScriptClasspath
import pod.cli.script.ScriptHost
import pod.cli.script.ScriptOutcome
import pod.cli.gcs.GcsWatcher
import pod.cli.gcs.gcsOption
import pod.launch.FleetChoice
import pod.launch.FleetWatcher
import pod.launch.Interruption
import pod.launch.interruptionIn
import pod.mavlink.link.DeviceNotFound
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.LinkException
import pod.mavlink.link.PortInUse
import java.io.File
import java.io.IOException
import java.net.BindException
import java.net.InetSocketAddress
import java.nio.channels.DatagramChannel
import java.nio.channels.UnresolvedAddressException

/**
 * `pod run SCRIPT.main.kts`: compiles and runs a Kotlin script in this JVM with Pod on its
 * classpath, telling it which fleet to fly through the [FleetChoice] system properties.
 * Stopped by Ctrl-C or SIGTERM, the script's `pod { }` program is cancelled and its vehicles made
 * safe ([Interruption]); the command then exits with 130.
 */
internal class RunCommand : CliktCommand(name = "run") {
    private val script by argument("SCRIPT", help = "a .main.kts script")
    private val scriptArgs by argument("ARGS", help = "passed to the script as args (put them after --)").multiple()
    private val keyFile by keyFileOption()
    private val sim by option("--sim", metavar = "N", help = "fly N simulated vehicles (default: 4)").int().restrictTo(1..254)
    private val connect by option("--connect", metavar = "ADDR", help = "fly the vehicles on this link (udpin://0.0.0.0:14550, serial:///dev/ttyUSB0:57600, …)")
    private val timeScale by option("--time-scale", metavar = "X", help = "vehicle seconds per real second (default: 1): the simulated fleet's with --sim; with --connect, that of a simulator run faster (pod sim --time-scale X), so the program's durations count in vehicle time")
        .double().restrictTo(0.01..1000.0)
    private val gcs by gcsOption()

    override fun help(context: Context): String =
        "Run a .main.kts script with Pod on its classpath, on a simulated or a real fleet."

    override fun run() {
        val file = File(script)
        if (!file.isFile) badInput("no such script: $script")
        // Anything else would be compiled as Kotlin anyway, with a screenful of compiler errors.
        if (!file.name.endsWith(".kts")) {
            badInput("$script is not a Kotlin script: pod run takes a .main.kts file (to send a QGC WPL mission, use 'pod mission upload $script')")
        }
        val choice = fleetChoice()
        // `--gcs`: every `pod { }` program the script starts serves the ground station's page for its fleet.
        val page = gcs?.let { at ->
            GcsWatcher.refusal(at)?.let(::badInput)
            GcsWatcher(at) { server -> echo("pod: ground station: open ${server.url}", err = true) }
        }
        val outcome = try {
            withSystemProperties(choice.toSystemProperties()) {
                watchedBy(page) {
                    ScriptHost(ScriptClasspath.forScripts()).run(
                        file, scriptArgs,
                        compiling = { echo("pod: compiling ${file.name} (about 10 s for a new or changed script; later runs start at once)", err = true) },
                    ) { echo(it, err = true) }
                }
            }
        } catch (e: Throwable) {
            // The scripting host may let the cancellation through rather than report it.
            val interrupted = interruptionIn(e) ?: throw e
            throw stopped(interrupted.signal)
        }
        when (outcome) {
            ScriptOutcome.Completed -> Unit
            // A script that does not compile is bad input, like a malformed file: exit 2.
            is ScriptOutcome.CompileFailed -> throw CliktError(outcome.messages.joinToString("\n"), statusCode = Exit.USAGE)
            is ScriptOutcome.Threw -> {
                interruptionIn(outcome.error)?.let { throw stopped(it.signal) }
                // The link named by --connect could not be opened (taken since the check above).
                generateSequence(outcome.error) { it.cause }.filterIsInstance<LinkException>().firstOrNull()?.let {
                    badInput(it.message ?: it.toString())
                }
                val what = outcome.error.message ?: outcome.error.javaClass.name
                val where = outcome.line?.let { " (${file.name}:$it)" }.orEmpty()
                throw CliktError("error: $what$where", statusCode = 1)
            }
        }
    }

    private fun stopped(signal: String) = CliktError("pod: stopped by $signal", statusCode = Interruption.EXIT_CODE)

    private fun fleetChoice(): FleetChoice {
        val address = connect
        return when {
            address != null && sim != null -> throw UsageError("--sim and --connect exclude each other")
            address != null -> {
                val parsed = reportingLinkErrors { LinkAddress.parse(address) }
                // A port that cannot be bound is bad input (exit 2), found before the script compiles.
                // Only listening is tried: it takes nothing from anyone, where a TCP connect would.
                if (parsed is LinkAddress.UdpIn && parsed.port != 0) tryListening(parsed)
                if (parsed is LinkAddress.Serial && parsed.path.startsWith("/") && !java.io.File(parsed.path).exists()) badInput(DeviceNotFound(parsed).message!!)
                signingKey(keyFile) // a malformed key is bad input (exit 2), found before the script compiles
                FleetChoice.Connect(address, timeScale ?: 1.0, keyFile?.toString())
            }
            else -> FleetChoice.Sim(sim ?: 4, timeScale ?: 1.0)
        }
    }
}

/**
 * Binds [address] for a moment, as the script's link will: a port in use ends `pod run` with exit 2
 * before the script compiles. A plain channel, closed at once, so the port is free again when the
 * script binds it.
 */
private fun tryListening(address: LinkAddress.UdpIn) {
    try {
        DatagramChannel.open().use { it.bind(InetSocketAddress(address.host, address.port)) }
    } catch (e: BindException) {
        badInput(if (e.message.orEmpty().contains("in use", ignoreCase = true)) PortInUse(address, e).message!! else "cannot listen on ${address.hostAndPort}: ${e.message}")
    } catch (e: UnresolvedAddressException) {
        badInput("cannot listen on ${address.hostAndPort}: unknown host '${address.host}'")
    } catch (e: IOException) {
        badInput("cannot listen on ${address.hostAndPort}: ${e.message}")
    }
}

/** Runs [block] with [watcher] watching the programs it starts, or just runs it when there is none. */
private fun <T> watchedBy(watcher: FleetWatcher?, block: () -> T): T = if (watcher == null) block() else FleetWatcher.around(watcher, block)

/** Runs [block] with [properties] set, restoring what was there before (tests run `pod` in-process). */
private inline fun <T> withSystemProperties(properties: Map<String, String>, block: () -> T): T {
    val before = properties.keys.associateWith { System.getProperty(it) }
    properties.forEach { (k, v) -> System.setProperty(k, v) }
    try {
        return block()
    } finally {
        before.forEach { (k, v) -> if (v == null) System.clearProperty(k) else System.setProperty(k, v) }
    }
}
