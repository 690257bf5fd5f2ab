package pod.bench

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.runBlocking
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import java.io.File
import java.lang.management.ManagementFactory
import java.net.InetSocketAddress
import java.net.StandardSocketOptions
import java.nio.ByteBuffer
import java.nio.channels.ClosedChannelException
import java.nio.channels.DatagramChannel
import java.util.Locale
import java.util.concurrent.locks.LockSupport
import kotlin.concurrent.thread
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds


/** CPU time per live JVM thread, to see where a receive path spends it. */
object ThreadCpu {
    fun snapshot(): Map<Long, Pair<String, Long>> {
        val bean = ManagementFactory.getThreadMXBean()
        return bean.allThreadIds.associateWith { id -> (bean.getThreadInfo(id)?.threadName ?: "?") to bean.getThreadCpuTime(id) }
            .filterValues { it.second >= 0 }
    }

    fun print(before: Map<Long, Pair<String, Long>>, after: Map<Long, Pair<String, Long>>, label: String) {
        println("    thread CPU during $label:")
        after.map { (id, nameAndCpu) -> nameAndCpu.first to nameAndCpu.second - (before[id]?.second ?: 0L) }
            .filter { it.second > 1_000_000 }
            .sortedByDescending { it.second }
            .forEach { (name, nanos) -> println(String.format(Locale.ROOT, "      %8.1f ms  %s", nanos / 1e6, name)) }
    }
}

/** Linux's UDP counters: where datagrams that never reached a receiver went. */
object KernelUdpCounters {
    /** `Udp: RcvbufErrors` from /proc/net/snmp (datagrams dropped because a receive buffer was full), or -1. */
    fun receiveBufferErrors(): Long = try {
        val lines = File("/proc/net/snmp").readLines().filter { it.startsWith("Udp: ") }
        val names = lines[0].split(' ')
        val values = lines[1].split(' ')
        values[names.indexOf("RcvbufErrors")].toLong()
    } catch (_: Exception) {
        -1
    }
}
