package pod.cli.gcs

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.double
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.cancel
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext
import pod.cli.Output
import pod.cli.badInput
import pod.cli.keyFileOption
import pod.cli.reportingLinkErrors
import pod.cli.signedConfig
import pod.cli.signingKey
import pod.launch.Interrupted
import pod.launch.Interruption
import pod.mavlink.GroundStation
import pod.sim.SimFlavor
import pod.sim.SimPlatform

/**
 * `pod gcs`: the ground station in the browser. Serves the page ([GcsServer]) for the vehicles on
 * a link (`--connect`) or for simulated ones it starts itself (`--sim N`), prints the URL to open,
 * and runs until interrupted; then whatever a page started (a queue, a survey) is stopped and its
 * vehicle left holding.
 */
internal class GcsCommand(private val out: Output) : CliktCommand(name = "gcs") {
    private val connect by option("--connect", help = "link to the vehicles (udpin:, udpout:, tcp:, serial:///dev/ttyUSB0:57600)").default("udpin:0.0.0.0:14550")
    private val sim by option("--sim", metavar = "N", help = "simulate N copters on loopback instead of connecting (then --connect is not used)").int().restrictTo(1..254)
    private val timeScale by option("--time-scale", metavar = "X", help = "vehicle seconds per real second: the simulated fleet's, or an external simulator's").double().restrictTo(0.01..1000.0).default(1.0)
    private val http by option("--http", metavar = "HOST:PORT", help = "where to serve the page; beyond loopback it needs the token printed with the URL (port 0: any free one)")
        .convert { text -> HttpAddress.parse(text) ?: fail("not HOST:PORT with a port in 0..65535: '$text'") }
        .default(HttpAddress("127.0.0.1", 8080), defaultForHelp = "127.0.0.1:8080")
    private val tiles by option("--tiles", metavar = "URL", help = "map tiles under the vehicles, as a template with {z}, {x} and {y} (default: an offline metric grid)")
        .convert { if ("{z}" in it && "{x}" in it && "{y}" in it) it else fail("the tile URL needs {z}, {x} and {y}: '$it'") }
    private val keyFile by keyFileOption()

    override fun help(context: Context): String = "The ground station in the browser: the fleet live on a map, with commands, mission queues, surveys and plans."

    override fun run() = runBlocking {
        // Two scopes: the link (station, simulated vehicles) outlives what the pages started, so
        // that stopping the pages' work can still tell each vehicle to hold before the link closes.
        val parent = coroutineContext[Job]
        val links = CoroutineScope(coroutineContext + SupervisorJob(parent))
        val pages = CoroutineScope(coroutineContext + SupervisorJob(parent))
        val simulated = sim?.let { n -> SimPlatform.start(links, List(n) { SimFlavor.ARDUCOPTER }, timeScale, configure = SurveySimWorld.configure()) }
        val station = simulated?.station ?: reportingLinkErrors {
            GroundStation.open(connect, links, signedConfig(signingKey(keyFile)))
        }
        suspend fun closeAll() {
            if (!pages.stopPageWork()) out.line("some vehicles may not have been told to hold: what the pages started did not stop within 10 s")
            withContext(NonCancellable) { simulated?.close() ?: station.closeAndAwait() }
            links.cancel()
        }
        val source = if (sim != null) "$sim simulated copters" else connect
        val fleet = GcsFleet(station, pages, source, timeScale, tiles)
        val server = try {
            GcsServer.start(fleet, http.host, http.port)
        } catch (e: GcsRequestException) {
            closeAll()
            badInput(e.message!!)
        }
        out.line("pod gcs: $source; open ${server.url}")
        if (server.access.token != null) out.line("the token is in that URL: every request needs it (printed once)")
        try {
            Interruption.cancellable("stopping what the pages started and leaving their vehicles holding") { awaitCancellation() }
        } catch (e: Interrupted) {
            throw CliktError("pod: stopped by ${e.signal}", statusCode = Interruption.EXIT_CODE)
        } finally {
            server.close()
            closeAll()
        }
    }
}

/** `HOST:PORT` of `--http`; an IPv6 host in brackets (`[::1]:8080`). */
internal data class HttpAddress(val host: String, val port: Int) {
    companion object {
        fun parse(text: String): HttpAddress? {
            if (':' !in text) return null // "8080" alone is not a host named 8080
            val host = if (text.startsWith("[")) text.substringAfter("[").substringBefore("]") else text.substringBeforeLast(":")
            val port = text.substringAfterLast(":").toIntOrNull()?.takeIf { it in 0..65535 } ?: return null
            if (host.isBlank() || (!text.startsWith("[") && ':' in host)) return null
            return HttpAddress(host, port)
        }
    }
}
