package pod.sim.world

import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import kotlin.math.cos
import kotlin.math.sin
import kotlin.math.sqrt
import kotlin.random.Random

/**
 * Something lying on the ground that a simulated photo "detects" when it falls inside the photo's
 * footprint (see [CameraFov]). It lies on the terrain: [location]'s altitude is ignored.
 */
public data class SimObject(
    /** Its number, unique in a scenario: what the ground learns of a detection (see pod.sim.SimDetections). */
    public val id: Int,
    /** Where it lies. */
    public val location: Location,
    /** What it is, for people reading a report. */
    public val label: String = "object",
) {
    /** Places objects in the simulated world. */
    public companion object {
        /**
         * [count] objects spread uniformly over the disc of [radius] around [center], numbered
         * from [firstId]; the same seed gives the same objects.
         */
        public fun scatter(seed: Long, count: Int, center: Location, radius: Distance, firstId: Int = 1, label: String = "object"): List<SimObject> {
            require(count >= 0) { "count must be ≥ 0, was $count" }
            require(radius.meters >= 0) { "radius must be ≥ 0, was $radius" }
            val random = Random(seed)
            return List(count) { i ->
                val d = radius.meters * sqrt(random.nextDouble())
                val a = random.nextDouble(0.0, 2 * Math.PI)
                SimObject(firstId + i, center.offset(north = (d * cos(a)).m, east = (d * sin(a)).m), label)
            }
        }
    }
}
