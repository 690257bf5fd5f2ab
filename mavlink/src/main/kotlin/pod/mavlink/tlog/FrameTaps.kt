package pod.mavlink.tlog

import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.TimeMark
import kotlin.time.TimeSource

/**
 * The recordings of one ground station ([pod.mavlink.GroundStation.record]): the taps that see
 * every frame it sends and receives, each stamped in microseconds since the Unix epoch from its own
 * start on the station's [clock]. A tap that throws is counted ([errors]), never passed on.
 */
internal class FrameTaps(private val clock: TimeSource) {
    private val taps = CopyOnWriteArrayList<ActiveTap>()
    private val failures = AtomicLong()

    /** True while any recording runs: the station then passes its frames on. */
    val active: Boolean get() = taps.isNotEmpty()

    /** Frames a tap failed on. */
    val errors: Long get() = failures.get()

    /** Starts passing frames to [tap], stamped from [startEpochMicros] on. */
    fun add(tap: FrameTap, startEpochMicros: Long): Recording {
        val active = ActiveTap(tap, startEpochMicros, clock.markNow())
        taps += active
        return Recording { taps.remove(active) }
    }

    /** Passes [bytes], which went [direction] just now, to every tap. */
    fun onFrame(direction: FrameDirection, bytes: ByteArray) {
        for (active in taps) {
            try {
                active.tap.onFrame(active.startEpochMicros + active.start.elapsedNow().inWholeMicroseconds, direction, bytes)
            } catch (e: Exception) {
                failures.incrementAndGet()
            }
        }
    }

    private class ActiveTap(val tap: FrameTap, val startEpochMicros: Long, val start: TimeMark)
}
