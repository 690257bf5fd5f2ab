package pod.launch

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.runTest
import pod.core.time.Timebase
import pod.core.units.m
import pod.mavlink.link.MemoryNetwork
import pod.sim.LinkOpener
import pod.sim.SimFlavor
import pod.sim.SimVehicleConfig
import pod.sim.world.Rangefinder
import pod.sim.world.SimObject

class SimulateConfigureTest : StringSpec({
    "simulate starts every vehicle with the configuration configure returns, and by default leaves it alone" {
        // Virtual time on an in-memory network: the subject is the pass-through, not sockets.
        runTest {
            val timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
            val network = MemoryNetwork(backgroundScope, timebase)
            val seeded = SimObject.scatter(seed = 7, count = 4, center = SimVehicleConfig.DEFAULT_HOME, radius = 50.m)
            val (configured, _) = simulate(
                listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4), timeScale = 1.0, timebase = timebase, openLink = LinkOpener.memory(network),
                configure = { it.copy(objects = seeded, rangefinder = Rangefinder()) },
            ) { sim -> listOf(1, 2).map { sim[it].config } }
            configured.map { it.objects } shouldBe listOf(seeded, seeded)
            configured.map { it.rangefinder } shouldBe listOf(Rangefinder(), Rangefinder())
            // The hook sees the configuration simulate would have used: the system ids are kept.
            configured.map { it.systemId } shouldBe listOf(1, 2)

            val (plain, _) = simulate(listOf(SimFlavor.ARDUCOPTER), timeScale = 1.0, timebase = timebase, openLink = LinkOpener.memory(network)) { sim ->
                sim[1].config
            }
            plain.objects.shouldBeEmpty()
            plain.rangefinder shouldBe null
        }
    }
})
