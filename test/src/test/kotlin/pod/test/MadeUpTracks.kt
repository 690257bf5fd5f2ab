package pod.test

import pod.core.units.Location
import pod.core.units.m
import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.sin
import kotlin.time.Duration.Companion.seconds

/** Tracks made up point by point, for the matchers' own tests. */
internal object MadeUpTracks {
    val home = Location(41.178, -8.596, 120.m)

    /** A track through the (seconds, north, east, up) samples; on the ground wherever up is 0. */
    fun track(vararg samples: List<Number>): Track = Track(
        1, "copter-1", home,
        samples.map { (t, n, e, u) ->
            val at = home.offset(n.m, e.m, u.m)
            TrackPoint.of(t.toDouble().seconds, at, home, onGround = u.toDouble() == 0.0)
        },
    )

    /** One second per sample, [turns] turns around (north, east) = [center] at [radius], counter-clockwise unless [clockwise], 30 m up. */
    fun circle(center: Pair<Double, Double>, radius: Double, turns: Double, clockwise: Boolean): Track {
        val steps = (turns * 36).toInt()
        val sign = if (clockwise) -1 else 1
        return track(
            *Array(steps + 1) { i ->
                val a = sign * 2 * PI * i / 36
                listOf(i, center.first + radius * sin(a), center.second + radius * cos(a), 30)
            },
        )
    }

    /** A location [north] and [east] of home. */
    fun at(north: Number, east: Number): Location = home.offset(north.m, east.m)
}
