package pod.launch

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.ints.shouldBeExactly
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.runTest
import pod.core.time.Timebase
import pod.core.units.m
import pod.mavlink.link.MemoryNetwork
import pod.sim.LinkOpener
import pod.dsl.pick
import pod.sim.SimFlavor
import java.util.Collections
import kotlin.time.Duration.Companion.seconds

class VehicleWaitsTest : StringSpec({
    "a program's waits on a booting vehicle are said as they happen: the mode refusal it waits out, each once" {
        runTest {
            val timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
            val network = MemoryNetwork(backgroundScope, timebase)
            val lines = Collections.synchronizedList(ArrayList<String>())
            simulate(
                listOf(SimFlavor.ARDUCOPTER), timeScale = 1.0, timebase = timebase, openLink = LinkOpener.memory(network),
                configure = { it.copy(positionReadyAfter = 3.seconds, navigationReadyAfter = 12.seconds) },
            ) { sim ->
                val showing = launch { showWaits(sim.platform.station, lines::add) }
                val vehicle = sim.platform.mavlink(pick { count(1) }[0])
                vehicle.action.getAirborne(10.m)
                showing.cancel()
            }
            lines shouldContain "vehicle 1: waiting: Mode change to GUIDED failed: requires position"
            lines.count { "requires position" in it } shouldBeExactly 1
        }
    }
})
