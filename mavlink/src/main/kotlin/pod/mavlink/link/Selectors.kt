package pod.mavlink.link

import io.ktor.network.selector.SelectorManager
import kotlinx.coroutines.Dispatchers

/**
 * The selectors of this process. TCP links register with one Ktor selector ([shared]); UDP links
 * with a small group of java.nio receive loops ([udp]), so that many links in one process (a
 * simulated fleet, `pod route`) hold a few threads, not one per socket.
 */
internal object Selectors {
    /**
     * The one Ktor selector every TCP link of this process registers its socket with. A selector parks a
     * Dispatchers.IO thread in `select()`; one per link exhausted the 64 IO threads at about 60 links
     * (a `SimFleet` of 100 answered commands in a median 500 ms, a third of them resent). One
     * selector serves any number of sockets. It lives as long as the process; closing a link closes
     * only its socket.
     */
    val shared: SelectorManager by lazy { SelectorManager(Dispatchers.IO) }

    /** The UDP receive loops, one per core at most (see [UdpReceiveLoops]). */
    val udp: UdpReceiveLoops by lazy { UdpReceiveLoops(UdpReceiveLoops.defaultSize()) }
}

/**
 * A fixed group of [UdpReceiveLoop]s; each new receiving link goes to the one with the fewest links.
 *
 * Why a group and not one loop per process: the handlers run in place on the loop's thread (decoding,
 * routing, protocol machines), so one thread caps what all links together can take at one core, and
 * a handler that stalls (a tlog write on a slow disk) stalls every link on its loop. One loop per
 * core lets a process use the cores it has, as separate threads did, while a fleet of hundreds of
 * links still holds only that many threads. Why not more: a loop at 1,000 vehicles (16,000
 * datagrams/s) is mostly idle (bench/fleet.sh), and more threads than cores cannot run at once.
 */
internal class UdpReceiveLoops(size: Int) {
    private val loops = List(size) { UdpReceiveLoop("pod-udp-receive-$it") }

    /** The loop with the fewest links now. */
    fun pick(): UdpReceiveLoop = loops.minBy { it.load }

    companion object {
        /** `pod.udp.receiveThreads` when set (benchmarks compare sizes), else the number of cores. */
        fun defaultSize(): Int =
            System.getProperty("pod.udp.receiveThreads")?.toIntOrNull()?.coerceIn(1, 64)
                ?: Runtime.getRuntime().availableProcessors().coerceIn(1, 64)
    }
}
