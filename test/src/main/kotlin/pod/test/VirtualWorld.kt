package pod.test

import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.TestScope
import pod.core.time.Timebase
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.MemoryNetwork
import pod.sim.LinkOpener
import pod.sim.fault.FaultConditions
import pod.sim.fault.LinkCounters
import pod.sim.fault.LinkFaults
import java.util.concurrent.ConcurrentHashMap

/**
 * The world one [VirtualFleet] run lives in: the test scheduler of [test] as the clock and
 * dispatcher of everything, and one [MemoryNetwork] whose datagrams towards the ground station
 * (a port opened `udpin`) suffer [up] and all others [down], each route from its own
 * [FaultConditions] seeded from [seed], so a run is repeatable whatever order routes open in.
 */
internal class VirtualWorld(test: TestScope, seed: Long, up: LinkFaults, down: LinkFaults) {
    /** The scheduler's clock and a dispatcher on it. */
    val timebase = Timebase(test.testScheduler.timeSource, StandardTestDispatcher(test.testScheduler))

    private val listening: MutableSet<Int> = ConcurrentHashMap.newKeySet()
    private val routes = FaultConditions.byDirection(seed, up, down) { it in listening }

    // (towards the station, the route's model), in the order routes were first used.
    private val models = ArrayList<Pair<Boolean, FaultConditions>>()

    /** The network; its coroutines live in the test's background scope. */
    val network = MemoryNetwork(test.backgroundScope, timebase) { from, to ->
        routes(from, to)?.also { synchronized(models) { models += (to.port in listening) to it } }
    }

    /** Opens links on [network], noting the ports that listen (the station's side of [up]). */
    val openLink = LinkOpener { address ->
        network.open(address).also { if (address is LinkAddress.UdpIn) listening += it.localPort }
    }

    /** What the faults did so far to datagrams towards the station, or away from it, summed over routes. */
    fun counters(towardsStation: Boolean): LinkCounters = synchronized(models) {
        models.filter { it.first == towardsStation }.map { it.second.model.counters }.fold(LinkCounters(), ::sum)
    }

    private fun sum(a: LinkCounters, b: LinkCounters) = LinkCounters(
        a.sent + b.sent, a.dropped + b.dropped, a.duplicated + b.duplicated,
        a.reordered + b.reordered, a.corrupted + b.corrupted, a.delivered + b.delivered, a.discarded + b.discarded,
    )
}
