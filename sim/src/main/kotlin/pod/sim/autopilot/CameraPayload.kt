package pod.sim.autopilot

import pod.core.units.Location
import pod.sim.PhotoEvent
import pod.sim.flight.horizontalDistance
import kotlin.time.Duration.Companion.seconds

/**
 * The camera payload on the vehicle side (core's `Camera` is the ground side's view of one): its
 * trigger: single shots, a time interval with an optional count
 * (IMAGE_START_CAPTURE) or a distance (DO_SET_CAM_TRIGG_DIST). Pure: [step] is fed the time and
 * position and returns the photos taken.
 */
internal class CameraPayload {
    private var interval: Double? = null
    private var remaining: Int = 0 // 0 = until stopped
    private var nextAt: Double = 0.0
    private var distance: Double? = null
    private var lastAt: Location? = null
    private var pendingShot = false
    private var pendingSeq: Int? = null // the mission item that asked for the pending shot
    private var taken = 0

    /** Take one photo on the next step, credited to mission item [seq] when a mission item asked. */
    fun shoot(seq: Int? = null) {
        pendingShot = true
        pendingSeq = seq
    }

    /** Photos every [seconds], [count] of them (0 = until stopped), the first now. */
    fun startInterval(seconds: Double, count: Int, now: Double) {
        distance = null
        if (seconds <= 0.0) {
            interval = null
            pendingShot = true
            return
        }
        interval = seconds
        remaining = count
        nextAt = now
    }

    /** A photo every [metres] flown (0 stops), the first now. */
    fun startDistance(metres: Double) {
        interval = null
        distance = metres.takeIf { it > 0 }
        lastAt = null
    }

    /** Stops interval and distance triggering. */
    fun stop() {
        interval = null
        distance = null
    }

    /** The photos due at [now] seconds with the vehicle at [location]. */
    fun step(now: Double, location: Location, missionSeq: Int?): List<PhotoEvent> {
        val photos = ArrayList<PhotoEvent>(1)
        fun take(seq: Int? = missionSeq) {
            photos += PhotoEvent(taken++, now.seconds, location, seq)
        }
        if (pendingShot) {
            pendingShot = false
            take(pendingSeq ?: missionSeq)
            pendingSeq = null
        }
        interval?.let { every ->
            if (now >= nextAt) {
                take()
                nextAt += every
                if (remaining > 0 && --remaining == 0) interval = null
            }
        }
        distance?.let { d ->
            val last = lastAt
            if (last == null || horizontalDistance(last, location) >= d) {
                take()
                lastAt = location
            }
        }
        return photos
    }
}
