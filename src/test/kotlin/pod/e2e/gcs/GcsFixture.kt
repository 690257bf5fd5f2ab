package pod.e2e.gcs

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.runBlocking
import pod.cli.gcs.GcsFleet
import pod.cli.gcs.GcsServer
import pod.cli.gcs.PageLimits
import pod.sim.SimFlavor
import pod.sim.SimPlatform
import pod.sim.SimVehicleConfig

/**
 * A `pod gcs` as the command runs it, in this JVM: [count] simulated vehicles on loopback UDP at
 * [timeScale], their ground station, and the server on a free loopback port (or [host]).
 */
internal class GcsFixture private constructor(
    val scope: CoroutineScope,
    val sim: SimPlatform,
    val fleet: GcsFleet,
    val server: GcsServer,
) : AutoCloseable {
    val url: String get() = server.url

    override fun close() {
        server.close()
        scope.cancel()
        sim.close()
    }

    companion object {
        suspend fun start(
            count: Int = 3,
            timeScale: Double = 5.0,
            host: String = "127.0.0.1",
            flavors: List<SimFlavor> = List(count) { SimFlavor.ARDUCOPTER },
            configure: (SimVehicleConfig) -> SimVehicleConfig = { it },
            tiles: String? = null,
            limits: PageLimits = PageLimits(),
        ): GcsFixture {
            val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
            val sim = SimPlatform.start(scope, flavors, timeScale, configure = configure)
            val fleet = GcsFleet(sim.station, scope, "${flavors.size} simulated copters", timeScale, tiles)
            val server = GcsServer.start(fleet, host, 0, limits = limits)
            return GcsFixture(scope, sim, fleet, server)
        }
    }
}

/** Runs [block] with a started fixture and a browser, closing both however it ends. */
internal fun withGcs(
    count: Int = 3,
    timeScale: Double = 5.0,
    configure: (SimVehicleConfig) -> SimVehicleConfig = { it },
    block: suspend (GcsFixture, GcsBrowser) -> Unit,
) = runBlocking {
    GcsFixture.start(count, timeScale, configure = configure).use { gcs ->
        GcsBrowser().use { browser -> block(gcs, browser) }
    }
}
