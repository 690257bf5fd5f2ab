package pod.mavlink.queue

import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.coroutineScope
import pod.mavlink.telemetry.ModeRole
import pod.mavlink.firmware.Firmware
import pod.mavlink.telemetry.FlightModes
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.collectLatest
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.distinctUntilChanged
import kotlinx.coroutines.flow.dropWhile
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.transformWhile
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.mission.SurveyPlanner
import pod.core.queue.MissionQueue
import pod.core.queue.QueueEntry
import pod.core.queue.QueuePattern
import pod.core.queue.WhenEmpty
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.isAirborne
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.CommandTimeout
import kotlin.math.abs
import kotlin.time.Duration

/**
 * Flies a [MissionQueue] on one MAVLink vehicle, element by element, in the vehicle's guided mode
 * ([GuidedSteering]): the ground holds the queue, so an insertion, a replacement or `next()` takes
 * effect with one acknowledged command (one round trip), and no mission on board is touched.
 *
 * It follows the queue's current element: a new one is commanded at once, the previous one's
 * commands are abandoned; arrival (within [QueueFlightConfig.arrivalRadius]) ends a goto, segment,
 * path or survey; the element's duration is timed here, on the station's clock; the target is
 * sent again every [QueueFlightConfig.refresh], so a vehicle that took a stale command late is put
 * right within that time. When the queue runs empty the vehicle holds where it is, at its altitude
 * (a multirotor on the point it has just reached; a plane circles there), and [fly] returns
 * ([WhenEmpty.COMPLETE]) or waits for more ([WhenEmpty.WAIT]). It starts with the queue's first element, waiting for one if the queue is empty.
 *
 * The vehicle must be flying: [QueueNotFlyable] otherwise. A command the vehicle refuses ends the
 * flight with [QueueElementRefused]; one that goes unanswered is sent again until the vehicle
 * answers or is lost. Cancelling [fly] leaves the vehicle where the last command put it: the caller
 * (the engine) makes it safe.
 */
public class QueueFlight(
    private val vehicle: MavlinkVehicle,
    private val queue: MissionQueue,
    private val config: QueueFlightConfig = QueueFlightConfig(),
) {
    private val steering = GuidedSteering(vehicle, config.circleSpeed)
    private val takeover = TakeoverWatch(vehicle, emptySet())

    /** The point a multirotor's last element ended on by arriving, or null: where an empty queue holds it. */
    @Volatile
    private var reached: Location? = null

    /** Flies the queue until it runs empty (see [WhenEmpty]) or the caller is cancelled. */
    public suspend fun fly(whenEmpty: WhenEmpty = WhenEmpty.COMPLETE) {
        val release = queue.claim(vehicle.toString())
        try {
            if (!vehicle.action.isFlying()) throw QueueNotFlyable(vehicle.systemId, "it is not flying (take off first)")
            val home = awaitHome()
            val arrival = arrivalRadius()
            takeover.allowed = steeredModes()
            coroutineScope {
                val clock = launch { keepTime() }
                launch { takeover.watch() }
                queue.state.map { it.current }.distinctUntilChanged()
                    .dropWhile { it == null }
                    .transformWhile { emit(it); it != null || whenEmpty == WhenEmpty.WAIT }
                    .collectLatest { entry -> if (entry == null) holdHere() else fly(entry, home, arrival) }
                coroutineContext.cancelChildren()
            }
        } finally {
            release()
        }
    }

    /** Ends elements whose duration runs out, on time, and refreshes the status about once a second. */
    private suspend fun keepTime() {
        while (true) {
            queue.expire()
            val now = queue.now()
            val untilDeadline = queue.state.value.deadline?.let { it - now }
            val wait = listOfNotNull(untilDeadline?.div(queue.timeScale), config.statusPeriod).min()  // the status period is wall time
            delay(wait.coerceAtLeast(Duration.ZERO))
        }
    }

    private suspend fun fly(entry: QueueEntry, home: Location, arrival: Distance) {
        reached = null
        val height = entry.element.altitude ?: currentHeight()
        fun at(point: pod.core.queue.QueuePoint) = absolute(point.resolve(home, height), home)
        when (val pattern = entry.element.pattern) {
            is QueuePattern.Goto -> through(listOf(at(pattern.point)), arrival)
            is QueuePattern.Segment -> through(listOfNotNull(leadIn(at(pattern.from), at(pattern.to)), at(pattern.from), at(pattern.to)), arrival)
            is QueuePattern.Path -> through(pattern.points.map(::at), arrival)
            is QueuePattern.Survey -> {
                val start = pattern.start.resolve(home, height)
                val points = SurveyPlanner.lawnMower(start, pattern.length, pattern.width, pattern.spacing, pattern.direction, height)
                through(points.map { absolute(it, home) }, arrival)
            }
            is QueuePattern.Circle -> {
                circle(at(pattern.center), pattern.radius)
                awaitCancellation()
            }
            QueuePattern.Hold -> {
                // Where it can stop: a moving multirotor held where it was heard brakes past that point and flies back.
                val here = vehicle.telemetry.position.value?.let { if (steering.isPlane) it.location else pod.mavlink.action.StoppingPoint.of(it) } ?: home
                steadily(absolute(here.copy(altitude = height), home)) { awaitCancellation() }
            }
            QueuePattern.Land -> {
                takeover.allowed += modeFor(ModeRole.LAND) + modeFor(ModeRole.MISSION) // an ArduPlane lands through its mission's sequence
                accepted { vehicle.action.land() }
                vehicle.action.awaitLanded(config.landingTimeout)
            }
            QueuePattern.ReturnHome -> {
                takeover.allowed += modeFor(ModeRole.RETURN)
                accepted { vehicle.action.returnToLaunch() }
                if (steering.isPlane) awaitNear(home, arrival, ignoreAltitude = true) else vehicle.action.awaitLanded(config.landingTimeout)
            }
        }
        queue.arrived(entry.id)
    }

    /**
     * Flies through [points] in order, each one reached before the next is commanded: a multirotor
     * straight at each (it stops on every point, so it flies the legs); a plane along each leg.
     */
    private suspend fun through(points: List<Location>, arrival: Distance) {
        reached = null
        var legStart = vehicle.telemetry.position.value?.location ?: points.first()
        for (point in points) {
            if (steering.isPlane) alongLeg(legStart.copy(altitude = point.altitude), point, arrival) else steadily(point) { awaitNear(point, arrival, ignoreAltitude = false) }
            legStart = point
        }
        if (!steering.isPlane) reached = points.last()
    }

    /**
     * For a plane, a point three loiter radii before [from] on the line from [to] through it: the
     * plane lines up there, so it flies the segment from its start instead of turning onto it
     * halfway (it cannot turn on the spot); null for a multirotor, which stops at [from].
     */
    private fun leadIn(from: Location, to: Location): Location? {
        if (!steering.isPlane) return null
        val (n, e) = to.northEastTo(from)
        val length = kotlin.math.hypot(n.meters, e.meters)
        if (length < 1.0) return null
        val extra = loiterRadius().meters * 3
        return from.offset((n.meters / length * extra).m, (e.meters / length * extra).m)
    }

    private fun loiterRadius(): Distance = steering.planeLoiterRadius ?: QueueFlightConfig.PLANE_LOITER_GUESS

    /**
     * Flies a plane along the leg [from]–[to] until it is within [arrival] of [to], by a target on
     * the leg more than three loiter radii ahead: that far, an ArduPlane flies straight at a guided
     * point from where it is (Plane::update_loiter's crosstrack branch) instead of turning onto the
     * circle around it, so moving the target along the leg keeps the plane on it.
     */
    private suspend fun alongLeg(from: Location, to: Location, arrival: Distance) {
        val lookahead = loiterRadius() * 3.5
        while (true) {
            val here = vehicle.telemetry.position.value?.location ?: from
            if (here.copy(altitude = to.altitude).distanceTo(to).meters <= arrival.meters) return
            accepted { steering.goTo(Carrots.onLine(from, to, here, lookahead)) }
            pause(config.circleStep)
        }
    }

    /** Commands [target], then runs [until], sending the target again every refresh period. */
    private suspend fun steadily(target: Location, until: suspend () -> Unit) = coroutineScope {
        accepted { steering.goTo(target) }
        val refresh = launch {
            while (true) {
                pause(config.refresh)
                accepted { steering.goTo(target) }
            }
        }
        until()
        refresh.cancel()
    }

    private suspend fun circle(center: Location, radius: Distance) {
        if (!steering.circlesFromGround) {
            accepted { steering.circle(center, radius) }
            while (true) {
                pause(config.refresh)
                accepted { steering.circle(center, radius) }
            }
        }
        while (true) {
            val here = vehicle.telemetry.position.value?.location ?: center
            val lead = Carrots.lead(radius, config.circleSpeed, config.circleStep.inWholeMilliseconds / 1000.0 * 3)
            accepted { steering.goTo(Carrots.onCircle(center, radius, here, lead).copy(altitude = center.altitude)) }
            pause(config.circleStep)
        }
    }

    /**
     * Holds a multirotor on the point it has just reached (an arrival counts a couple of metres
     * out, and the position heard is a round trip old: holding "here" would stop it short of the
     * point, up to 1.9 m at 100 ms RTT in the issue-15 waypoint benchmark), or where it can stop
     * after anything else (a circle, a hold, a skipped element); a plane circles where it is.
     */
    private suspend fun holdHere() {
        if (!airborne()) return
        reached?.let { point ->
            accepted { steering.goTo(point) }
            return
        }
        // Still moving (a skipped element, a cancelled circle): a multirotor stops where its
        // braking takes it, by its autopilot's hold (BRAKE, PX4's Hold); a goto to where it was
        // heard would brake past that point and fly back (25 m at 10 m/s on ArduCopter).
        if (!steering.isPlane) {
            accepted { vehicle.action.hold() }
            return
        }
        val here = vehicle.telemetry.position.value?.location ?: return
        accepted { steering.goTo(here) }
    }

    /** Runs [command] until the vehicle answers it: a command lost [CommandTimeout] is sent again; a refusal ends the flight. */
    private suspend fun accepted(command: suspend () -> Unit) {
        while (true) {
            try {
                command()
                return
            } catch (e: CommandTimeout) {
                continue
            } catch (e: pod.mavlink.command.CommandRejected) {
                throw QueueElementRefused(vehicle.systemId, queue.state.value.current, e)
            } catch (e: pod.mavlink.action.ActionException) {
                throw QueueElementRefused(vehicle.systemId, queue.state.value.current, e)
            }
        }
    }

    private suspend fun awaitNear(target: Location, within: Distance, ignoreAltitude: Boolean) {
        combine(vehicle.telemetry.position, vehicle.connection) { p, _ -> p }.filterNotNull().first { p ->
            val horizontal = p.location.copy(altitude = target.altitude).distanceTo(target).meters
            horizontal <= within.meters && (ignoreAltitude || abs(p.location.altitude.meters - target.altitude.meters) <= config.altitudeTolerance.meters)
        }
    }

    /** Waits [vehicleTime] of the vehicle's time (a simulator may run faster than the clock: the queue's time scale). */
    private suspend fun pause(vehicleTime: Duration) = delay(vehicleTime / queue.timeScale)

    /**
     * The modes Pod flies a queue in: the guided mode, its hold (BRAKE, Hold, a plane's LOITER),
     * PX4's orbit for a multicopter's circle ([GuidedSteering]); a landing or return adds its own.
     */
    private fun steeredModes(): Set<String> =
        setOf(modeFor(ModeRole.GUIDED), modeFor(ModeRole.HOLD)).flatten().toSet() + if (steering.circlesFromGround) emptySet() else setOf(PX4_ORBIT)

    private fun modeFor(role: ModeRole): List<String> = vehicle.identity.value.let { listOfNotNull(FlightModes.forRole(it.autopilot, it.type, role)) }

    private fun airborne(): Boolean = vehicle.telemetry.let { isAirborne(it.landedState.value, it.position.value?.relativeAltitude, it.armed.value) }

    private companion object {
        /** PX4's orbit mode, which a multicopter's DO_ORBIT switches to ([GuidedSteering.circle]). */
        const val PX4_ORBIT = "POSCTL.ORBIT"
    }

    private fun currentHeight(): Distance = vehicle.telemetry.position.value?.relativeAltitude ?: config.defaultHeight

    /** [location] (altitude above home) as an altitude above sea level. */
    private fun absolute(location: Location, home: Location): Location = location.copy(altitude = (home.altitude.meters + location.altitude.meters).m)

    private suspend fun awaitHome(): Location {
        vehicle.telemetry.home.value?.let { return it }
        return withTimeoutOrNull(config.homeTimeout) { vehicle.telemetry.home.filterNotNull().first() }
            ?: throw QueueNotFlyable(vehicle.systemId, "it reported no home within ${config.homeTimeout}")
    }

    /** How close counts as arrived: the configured radius, or per airframe (a plane: its loiter radius and a margin). */
    private suspend fun arrivalRadius(): Distance {
        config.arrivalRadius?.let { return it }
        if (!steering.isPlane) return QueueFlightConfig.MULTIROTOR_ARRIVAL
        val name = Firmware.of(vehicle.identity.value).loiterRadiusParam
        val loiter = try {
            withTimeoutOrNull(config.paramTimeout) { abs(vehicle.params.read(name).value) }
        } catch (e: pod.core.PodException) {
            null
        }
        steering.planeLoiterRadius = loiter?.takeIf { it > 1 }?.m
        return ((loiter ?: QueueFlightConfig.PLANE_LOITER_GUESS.meters) + QueueFlightConfig.PLANE_ARRIVAL_MARGIN.meters).m
    }
}
