package pod.mavlink.telemetry

import kotlin.time.Duration
import kotlin.time.TimeMark

/**
 * The last few notices, warnings and errors (STATUSTEXT) a vehicle sent, each with when it came:
 * the vehicle's own words that a failure quotes (a failsafe says why as, or just before, it takes
 * control: "Polygon fence breached", "Failsafe activated", "Crash: flew into terrain").
 */
internal class RecentNotices(private val keep: Int = 8) {
    private val heard = ArrayDeque<Pair<String, TimeMark>>()

    /** Notes [text], heard at [at]. */
    fun add(text: String, at: TimeMark): Unit = synchronized(heard) {
        heard.addLast(text to at)
        while (heard.size > keep) heard.removeFirst()
    }

    /** The texts heard no longer than [window] ago, oldest first. */
    fun within(window: Duration): List<String> = synchronized(heard) { heard.filter { it.second.elapsedNow() <= window }.map { it.first } }
}
