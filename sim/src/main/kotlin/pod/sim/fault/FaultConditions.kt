package pod.sim.fault

import io.ktor.network.sockets.InetSocketAddress
import pod.mavlink.link.LinkConditions
import pod.mavlink.link.TimedDatagram
import kotlin.random.Random
import kotlin.time.Duration

/**
 * A seeded [FaultModel] as the [LinkConditions] of one direction of a
 * [pod.mavlink.link.MemoryNetwork] route, so the faults a [LossyRelay] applies between sockets
 * apply to an in-memory link too, deterministic for the seed.
 */
public class FaultConditions(
    /** The model that decides each datagram's fate; its [FaultModel.counters] say what happened. */
    public val model: FaultModel,
) : LinkConditions {
    /** A fresh model of [faults] seeded with [seed]. */
    public constructor(faults: LinkFaults, seed: Long) : this(FaultModel(faults, seed))

    override fun offer(bytes: ByteArray, now: Duration): List<TimedDatagram> = model.offer(bytes, now).map { TimedDatagram(it.at, it.bytes) }

    override val nextRelease: Duration? get() = model.nextRelease

    override fun release(now: Duration): List<TimedDatagram> = model.release(now).map { TimedDatagram(it.at, it.bytes) }

    /** Ways to make fault conditions. */
    public companion object {
        /**
         * The `conditions` of a [pod.mavlink.link.MemoryNetwork] whose datagrams towards a port in
         * [groundPorts] (the ground station's) suffer [up] and all others [down], every route with
         * its own model seeded from [seed] and the route's addresses, so a run is repeatable
         * whatever order the routes are first used in. A direction with [LinkFaults.None] gets no
         * model (a perfect link).
         */
        public fun byDirection(
            seed: Long,
            up: LinkFaults = LinkFaults.None,
            down: LinkFaults = LinkFaults.None,
            groundPorts: (Int) -> Boolean,
        ): (InetSocketAddress, InetSocketAddress) -> FaultConditions? = { from, to ->
            val faults = if (groundPorts(to.port)) up else down
            if (faults.isNone) null else FaultConditions(faults, Random(seed xor (from.toString() + ">" + to.toString()).hashCode().toLong()).nextLong())
        }
    }
}
