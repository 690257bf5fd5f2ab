package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainInOrder
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.comparables.shouldBeLessThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.should
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.async
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.queue.EndReason
import pod.core.queue.MissionQueue
import pod.core.queue.QueueEvent
import pod.core.queue.at
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.dsl.queue.circle
import pod.dsl.queue.goto
import pod.dsl.queue.path
import pod.dsl.queue.segment
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.queue.QueueFlight
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import pod.test.Turn
import pod.test.circleAround
import pod.test.stayInCorridor
import kotlin.math.abs
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * The scenario on each autopilot, checked from the track the simulated vehicle really
 * flies: append three gotos; prepend a counter-clockwise circle for 60 s; replace the current
 * element with a segment; replace everything with a five-point path; skip the rest of it with
 * `next()`. Plane patterns are [Flavour.scale] times larger (a plane cannot turn on a copter's
 * circle).
 */
class QueueFlightSpec : StringSpec({

    for (flavour in Flavour.entries.filter { it.ready }) {
        "${flavour.label}: appended gotos, a prepended timed circle, a replaced segment and a replacing path are flown as the queue says" {
            virtualRun(seed = 14) { flying(flavour.config) { v, sim -> scenario(flavour, v, sim) } }
        }

        "${flavour.label}: the same under 20 % loss each way, the vehicle leaving every dropped element within ${HEADING_BOUND}" {
            val lossy = LinkFaults(drop = 0.2, reorder = 0.05, delay = 20.milliseconds, jitter = 10.milliseconds)
            // Heartbeats cross the same lossy link: allow more silence before calling the vehicle lost.
            virtualRun(seed = 15, up = lossy, down = lossy) { flying(flavour.config, GroundStationConfig(lostAfter = 10.seconds)) { v, sim -> scenario(flavour, v, sim) } }
        }
    }
})

/**
 * The vehicles the scenario runs on: patterns [scale] times the copter's, a [corridor] (m) the
 * track must keep to, and the [turn] a plane needs before it can head anywhere new.
 */
internal enum class Flavour(val label: String, val config: SimVehicleConfig, val scale: Double, val corridor: Double, val turn: Duration, val ready: Boolean = true) {
    // A copter brakes from cruise speed (5 m/s at 2.5 m/s²) before it can head anywhere new.
    ARDUCOPTER("ArduCopter", SimVehicleConfig(systemId = 61), 1.0, 4.0, 2.5.seconds),
    // A plane's corridor is its loiter radius (60 m): it joins lines in turns and circles the points it reaches.
    ARDUPLANE("ArduPlane", SimVehicleConfig(systemId = 62, type = VehicleType.FIXED_WING), 6.0, 60.0, 10.seconds),
    PX4_COPTER("PX4 copter", SimVehicleConfig(systemId = 63, autopilot = Autopilot.PX4), 1.0, 4.0, 2.5.seconds),
}

/** Takes off, runs the scenario on [v]'s queue while recording the flown track, and checks it. */
internal suspend fun CoroutineScope.scenario(flavour: Flavour, v: MavlinkVehicle, sim: SimVehicle) {
    val k = flavour.scale
    val height = 30.0
    Flights.keepArmedOnGround(v)
    v.action.arm()
    v.action.takeoff((if (flavour.config.type == VehicleType.FIXED_WING) 60 else 30).m)
    val home = v.telemetry.home.value!!
    val queue: MissionQueue = v.queue
    val events = mutableListOf<QueueEvent>()
    val recording = launch { queue.events.toList(events) }
    val track = FlownTrack(queue, sim, home)
    val sampling = track.start(this)
    val flight = async { QueueFlight(v, queue).fly() }

    val g1 = queue.append(goto(at((80 * k).m, 0.m), altitude = height.m))
    val g2 = queue.append(goto(at((80 * k).m, (80 * k).m), altitude = height.m))
    queue.append(goto(at(0.m, (80 * k).m), altitude = height.m))
    awaitEvent(queue) { it is QueueEvent.Started && it.entry == g2 }

    val center = 40 * k to 40 * k
    val radius = 25 * k
    val circle = queue.prepend(circle(at(center.first.m, center.second.m), (-radius).m, altitude = height.m, duration = 60.seconds))
    val circleStart = queue.now()
    val circleEnd = awaitEvent(queue) { it is QueueEvent.Ended && it.entry == circle } as QueueEvent.Ended
    circleEnd.reason shouldBe EndReason.ELAPSED
    (circleEnd.at - circleStart) shouldBe 60.seconds

    val from = 40 * k to -20 * k
    val to = -40 * k to -20 * k
    val seg = queue.replaceCurrent(segment(at(from.first.m, from.second.m), at(to.first.m, to.second.m), altitude = height.m))
    val segStart = queue.now()
    val segEnd = awaitEvent(queue) { it is QueueEvent.Ended && it.entry == seg } as QueueEvent.Ended
    segEnd.reason shouldBe EndReason.ARRIVED

    val points = listOf(0.0 to 0.0, 30.0 to 30.0, 60.0 to 0.0, 30.0 to -30.0, 0.0 to -60.0).map { (n, e) -> n * k to e * k }
    val pathEntry = queue.replaceAll(path(points.map { (n, e) -> at(n.m, e.m) }, altitude = height.m))
    val pathStart = queue.now()
    withTimeout(30.minutes) { sim.state.first { s -> home.northEastTo(s.location).let { (n, e) -> kotlin.math.hypot(n.meters - points[2].first, e.meters - points[2].second) < arrival(flavour) } } }
    val skippedAt = queue.now()
    queue.next()
    withTimeout(5.minutes) { flight.await() }
    // Holding: watch a while longer.
    kotlinx.coroutines.delay(40.seconds)
    sampling.cancel()
    recording.cancel()

    // Order of what the queue flew.
    events.filterIsInstance<QueueEvent.Ended>().map { it.entry.id to it.reason } shouldContainInOrder listOf(
        g1.id to EndReason.ARRIVED, g2.id to EndReason.PREEMPTED, circle.id to EndReason.ELAPSED,
        g2.id to EndReason.REPLACED, seg.id to EndReason.ARRIVED, pathEntry.id to EndReason.SKIPPED,
    )
    queue.state.value.isEmpty shouldBe true

    // The circle: once on it, inside the corridor, counter-clockwise, until its 60 s ran out.
    val onCircle = track.between(circleStart, circleEnd.at).dropWhile { abs(it.distanceTo(center.first, center.second) - radius) > flavour.corridor / 2 }
    onCircle.forEach { abs(it.distanceTo(center.first, center.second) - radius) shouldBeLessThan flavour.corridor }
    onCircle.asTrack(home) should circleAround(home.offset(center.first.m, center.second.m), Turn.COUNTER_CLOCKWISE, turns = (if (k > 1) 180.0 else 300.0) / 360)
    // Its duration honoured at the vehicle: still circling 2 s before the end, heading away within 2 s after.
    val justBefore = track.between(circleEnd.at - 2.seconds, circleEnd.at - 1.seconds).first()
    abs(justBefore.distanceTo(center.first, center.second) - radius) shouldBeLessThan flavour.corridor
    val bound = HEADING_BOUND + flavour.turn
    track.headingFor(from, circleEnd.at) shouldBeLessThan bound
    // Every change reached the vehicle within the bound: the segment dropped what was current, the
    // path dropped everything, next() dropped the rest of the path (the vehicle stops).
    track.headingFor(from, segStart) shouldBeLessThan bound
    track.headingFor(points[0], pathStart) shouldBeLessThan bound

    // The segment: once at its start and on the line (a plane joins it in a turn), along the line
    // to its end, for most of its length.
    val onSegment = track.between(segStart, segEnd.at)
        .dropWhile { it.distanceTo(from.first, from.second) > arrival(flavour) }
        .dropWhile { it.offSegment(from, to) > flavour.corridor / 2 }
    onSegment.isNotEmpty() shouldBe true
    onSegment.first().distanceTo(to.first, to.second) shouldBeGreaterThan 0.6 * kotlin.math.hypot(to.first - from.first, to.second - from.second)
    onSegment.asTrack(home) should stayInCorridor(home.offset(from.first.m, from.second.m), home.offset(to.first.m, to.second.m), width = (2 * flavour.corridor).m)

    // The path: its first three points in order, then no further after next().
    val flownPath = track.between(pathStart, skippedAt)
    // (the track is sampled: allow what the vehicle flies between samples)
    val reachedAt = points.take(3).map { p -> flownPath.indexOfFirst { it.distanceTo(p.first, p.second) < arrival(flavour) * 1.1 + 1 } }
    reachedAt.none { it < 0 } shouldBe true
    reachedAt shouldBe reachedAt.sorted()

    if (flavour.config.type != VehicleType.FIXED_WING) {
        val stopped = track.samples.zipWithNext().first { (p, q) -> p.at >= skippedAt && q.distanceTo(p.north, p.east) / (q.at - p.at).inWholeMilliseconds * 1000 < 0.5 }.first
        (stopped.at - skippedAt) shouldBeLessThan HEADING_BOUND + 5.seconds // the command, then braking from cruise speed
    }

    // Holding at altitude at the end, never descending.
    val holding = track.between(skippedAt + 20.seconds, track.last().at)
    holding.forEach { it.height shouldBeGreaterThan height - 3 }
    if (flavour.config.type != VehicleType.FIXED_WING) {
        holding.forEach { it.distanceTo(holding.first().north, holding.first().east) shouldBeLessThan 3.0 }
    }
}

/** How soon after a change the vehicle must be heading for the new element (one refresh period of QueueFlight). */
internal val HEADING_BOUND: Duration = 3.seconds

/**
 * How long after [since] the vehicle first flew towards [target] (north, east), its velocity
 * (from consecutive samples) within 45° of the bearing to it; infinite when it never did.
 */
internal fun FlownTrack.headingFor(target: Pair<Double, Double>, since: Duration): Duration {
    val pairs = samples.filter { it.at >= since }.zipWithNext()
    val first = pairs.firstOrNull { (p, q) ->
        val vn = q.north - p.north
        val ve = q.east - p.east
        val tn = target.first - p.north
        val te = target.second - p.east
        val speed = kotlin.math.hypot(vn, ve)
        val dist = kotlin.math.hypot(tn, te)
        speed > 1e-3 && dist > 1e-3 && (vn * tn + ve * te) / (speed * dist) > 0.7
    } ?: return Duration.INFINITE
    return first.first.at - since
}

private fun arrival(flavour: Flavour): Double = if (flavour.config.type == VehicleType.FIXED_WING) 100.0 else 3.0

private suspend fun awaitEvent(queue: MissionQueue, timeout: Duration = 30.minutes, match: (QueueEvent) -> Boolean): QueueEvent =
    withTimeout(timeout) { queue.events.filterIsInstance<QueueEvent>().first(match) }
