package pod.e2e

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import pod.core.queue.MissionQueue
import pod.core.units.Location
import pod.core.units.m
import pod.sim.SimVehicle
import kotlin.math.hypot
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds

/** One sample of a flown track: queue time, metres north and east of home, height above home. */
internal data class TrackPoint(val at: Duration, val north: Double, val east: Double, val height: Double) {
    fun distanceTo(north: Double, east: Double): Double = hypot(this.north - north, this.east - east)
}

/** The track a simulated vehicle really flies (its physical state, not its telemetry), sampled every [every]. */
internal class FlownTrack(private val queue: MissionQueue, private val sim: SimVehicle, private val home: Location) {
    private val points = java.util.Collections.synchronizedList(ArrayList<TrackPoint>())

    val samples: List<TrackPoint> get() = synchronized(points) { points.toList() }

    fun start(scope: CoroutineScope, every: Duration = 250.milliseconds): Job = scope.launch {
        while (true) {
            val s = sim.state.value
            val (n, e) = home.northEastTo(s.location)
            points += TrackPoint(queue.now(), n.meters, e.meters, s.relativeAltitude.meters)
            delay(every)
        }
    }

    fun between(from: Duration, to: Duration): List<TrackPoint> = samples.filter { it.at in from..to }

    fun last(): TrackPoint = samples.last()
}

/** Metres a point lies from the segment [a]–[b] (north, east pairs). */
internal fun TrackPoint.offSegment(a: Pair<Double, Double>, b: Pair<Double, Double>): Double {
    val (an, ae) = a
    val (bn, be) = b
    val ln = bn - an
    val le = be - ae
    val length2 = ln * ln + le * le
    val t = (((north - an) * ln + (east - ae) * le) / length2).coerceIn(0.0, 1.0)
    return hypot(north - (an + t * ln), east - (ae + t * le))
}

/**
 * These samples as a pod-test track from [home], for pod-test's track matchers (their failures say
 * where and when a rule broke).
 */
internal fun List<TrackPoint>.asTrack(home: Location): pod.test.Track =
    pod.test.Track(0, "the vehicle", home, map { pod.test.TrackPoint.of(it.at, home.offset(it.north.m, it.east.m, it.height.m), home, onGround = false) })
