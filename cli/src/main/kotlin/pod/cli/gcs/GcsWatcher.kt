package pod.cli.gcs

import com.github.ajalt.clikt.core.ParameterHolder
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.options.optionalValue
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.runBlocking
import pod.core.engine.EngineEvent
import pod.launch.FleetWatcher
import pod.mavlink.GroundStation

/**
 * Serves the ground station's page for a program's fleet while the program runs (`pod demo --gcs`,
 * `pod run --gcs`): the station's vehicles, and the program's events in the log. [announce] is
 * told the server once it listens (to print its URL). What a page starts runs in a scope of the
 * watch's own, stopped with it.
 */
internal class GcsWatcher(private val address: HttpAddress, private val announce: (GcsServer) -> Unit) : FleetWatcher {
    /** @throws GcsRequestException when the address cannot be bound. */
    override suspend fun watch(station: GroundStation, timeScale: Double, source: String): FleetWatcher.Watch {
        val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
        val fleet = GcsFleet(station, scope, source, timeScale)
        val server = try {
            GcsServer.start(fleet, address.host, address.port)
        } catch (e: Exception) {
            scope.cancel()
            throw e
        }
        announce(server)
        return object : FleetWatcher.Watch {
            override fun event(event: EngineEvent) = fleet.programEvent(event)

            override fun close() {
                server.close()
                // The program's station closes after this: what a page started holds its vehicle first.
                runBlocking { scope.stopPageWork() }
            }
        }
    }

    companion object {
        /** Where `--gcs` serves when given without a value. */
        val DEFAULT = HttpAddress("127.0.0.1", 8080)

        /**
         * Why [address] cannot be served, null when it can: bound for a moment and let go, so that
         * `pod run` says so before a script compiles (port 0 always can).
         */
        fun refusal(address: HttpAddress): String? {
            if (address.port == 0) return null
            return try {
                java.net.ServerSocket().use { it.bind(java.net.InetSocketAddress(address.host, address.port)) }
                null
            } catch (e: java.io.IOException) {
                "cannot serve the ground station on ${address.host}:${address.port}: ${e.message}"
            } catch (e: IllegalArgumentException) {
                "cannot serve the ground station on ${address.host}:${address.port}: ${e.message}"
            }
        }
    }
}

/** `--gcs [HOST:PORT]`: serve the ground station's page for the program's fleet (default 127.0.0.1:8080; port 0: any free one). */
internal fun ParameterHolder.gcsOption() =
    option("--gcs", metavar = "HOST:PORT", help = "also serve the ground station's page for this fleet, with the program's events in its log (default ${GcsWatcher.DEFAULT.host}:${GcsWatcher.DEFAULT.port}; port 0: any free one; beyond loopback it needs the token printed with the URL)")
        .convert { text -> HttpAddress.parse(text) ?: fail("not HOST:PORT with a port in 0..65535: '$text'") }
        .optionalValue(GcsWatcher.DEFAULT)
