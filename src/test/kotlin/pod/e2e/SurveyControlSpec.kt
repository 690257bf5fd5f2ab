package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldNotBeEmpty
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.survey.CameraTrigger
import pod.core.survey.PolygonSurvey
import pod.core.survey.SurveyPlan
import pod.core.survey.SurveySpacing
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.LandedState
import pod.core.workflow.CommandOutcome
import pod.core.workflow.ControlCommand
import pod.core.workflow.ControlPhase
import pod.core.workflow.ControlReport
import pod.core.workflow.ControlState
import pod.core.workflow.Forward
import pod.core.workflow.MissionControl
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.workflow.SurveyOperation
import pod.mavlink.workflow.SurveyWorkflow
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import java.util.Collections
import kotlin.math.hypot
import kotlin.random.Random
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * Mission control on a flying vehicle, as an operator's app drives it: two or three pauses, each
 * resumed, and in half the runs an abort, at random times, the vehicle's MAVLink link losing 20 % each way, and the app's link to
 * the flight delaying commands and delaying, reordering and losing a fifth of the reports. Each
 * seed is a property check in virtual time:
 * - the app never shows a state older than its last command (after a pause: paused, never
 *   executing; after an abort: aborted);
 * - a pause the flight applied holds position and altitude until the next command;
 * - an abort never descends before the vehicle is over home;
 * - the run ends landed at home, and the app converges on finished or aborted.
 */
class SurveyControlSpec : StringSpec({

    val runs = (1L..5L).map { Autopilot.ARDUPILOT to it } + (6L..8L).map { Autopilot.PX4 to it }
    for ((autopilot, seed) in runs) {
        "$autopilot seed $seed: random pause, resume and abort over lossy links: no stale state, pauses hold, an abort never descends before home, it ends at home" {
            val lossy = LinkFaults(drop = 0.2, reorder = 0.05, delay = 20.milliseconds, jitter = 10.milliseconds)
            val config = SimVehicleConfig(systemId = 93, autopilot = autopilot)
            virtualRun(seed = seed, up = lossy, down = lossy, timeout = 4.minutes) {
                flying(config, GroundStationConfig(lostAfter = 10.seconds)) { v, sim -> randomOperator(Random(seed), v, sim, timebase.clock) }
            }
        }
    }

    "the random runs above checked pauses that held and aborts that came home (the property is not vacuous)" {
        withClue("pauses checked: ${checked.pauses}, aborts checked: ${checked.aborts}") {
            (checked.pauses >= 8) shouldBe true
            (checked.aborts >= 2) shouldBe true
        }
    }

    "an app that restarts mid-flight finds the flight's state, and a station restarted on a flying vehicle holds it instead of assuming ready" {
        val config = SimVehicleConfig(systemId = 94, autopilot = Autopilot.ARDUPILOT)
        virtualRun(seed = 7) { flying(config) { v, _ ->
            Flights.keepArmedOnGround(v)
            val control = MissionControl<SurveyPlan>()
            val op = SurveyOperation(v, control, SurveyWorkflow(v), forward = { Forward(false, Unit) }, backward = { })
            val serving = launch { op.serve(flights = 1) }
            control.state.first { it.phase == ControlPhase.Ready }
            control.command(ControlCommand.Build(control.nextEventId(), plan(v)))
            control.command(ControlCommand.Start(control.nextEventId()))
            val flying = op.latest.first { it is ControlReport.Flying && (it.waypoint ?: 0) >= 2 }

            // The app restarts: a new controller attached to the flight shows it executing, not ready.
            val reattached = MissionControl.attachedTo<SurveyPlan>(op.latest.value)
            reattached.state.value.phase.shouldBeInstanceOf<ControlPhase.Executing>()
            (reattached.nextEventId() > flying.eventId) shouldBe true

            // The station restarts: the old operation is gone, a new one finds the vehicle in the air.
            serving.cancel()
            val fresh = MissionControl<SurveyPlan>()
            val again = SurveyOperation(v, fresh, SurveyWorkflow(v), forward = { Forward(false, Unit) }, backward = { })
            val serving2 = launch { again.serve(flights = 1) }
            val found = fresh.state.first { it.phase != ControlPhase.Waiting }.phase
            found.shouldBeInstanceOf<ControlPhase.Aborted>()
            v.telemetry.landedState.value shouldBe LandedState.IN_AIR
            withTimeout(30.seconds) { v.telemetry.mode.first { it?.name == "BRAKE" } }
            serving2.cancel()
        } }
    }
}) {
    private companion object {
        /** How many pauses and aborts the random runs checked. */
        object checked {
            @Volatile var pauses = 0

            @Volatile var aborts = 0
        }

        /** A 12-waypoint photo survey 20 m up, 90 × 60 m north-east of home. */
        fun plan(v: MavlinkVehicle): SurveyPlan {
            val home = v.telemetry.home.value!!
            val corners = listOf(0 to 0, 0 to 60, 90 to 60, 90 to 0).map { (n, e) -> home.offset((n + 20).m, (e + 20).m) }
            return PolygonSurvey.plan(corners, 20.m, SurveySpacing.Direct(30.m, 30.m), trigger = CameraTrigger.PER_WAYPOINT, start = v.telemetry.position.value!!.location)
        }

        data class Sample(val at: Duration, val north: Double, val east: Double, val height: Double)

        suspend fun CoroutineScope.randomOperator(rnd: Random, v: MavlinkVehicle, sim: SimVehicle, clock: kotlin.time.TimeSource) {
            Flights.keepArmedOnGround(v)
            val started = clock.markNow()
            fun now() = started.elapsedNow()
            val home = sim.state.value.home
            val control = MissionControl<SurveyPlan>()

            // The app's link to the flight: commands arrive 0–1.5 s late; reports too, reordered, a fifth lost.
            val delivered = MutableStateFlow(control.intent.value)
            val relay = launch {
                control.intent.collect { s ->
                    launch {
                        delay(rnd.nextLong(0, 1500).milliseconds)
                        delivered.update { if (it.state.eventId < s.state.eventId) s else it }
                    }
                }
            }
            val sent = Collections.synchronizedList(mutableListOf<Pair<Duration, ControlReport>>())
            val op = SurveyOperation(
                v, delivered,
                report = { r ->
                    sent += now() to r
                    if (rnd.nextDouble() >= 0.2) launch { delay(rnd.nextLong(0, 1500).milliseconds); control.report(r) }
                },
                workflow = SurveyWorkflow(v, actionTimeout = 10.seconds),
                forward = { visit -> visit.takePhoto(); Forward(flagged = visit.index % 4 == 1, value = Unit) },
                backward = { },
            )
            val seen = Collections.synchronizedList(mutableListOf<Pair<Duration, ControlState<SurveyPlan>>>())
            val watching = launch { control.state.collect { seen += now() to it } }
            val track = Collections.synchronizedList(mutableListOf<Sample>())
            val sampling = launch {
                while (true) {
                    val s = sim.state.value
                    val (n, e) = home.northEastTo(s.location)
                    track += Sample(now(), n.meters, e.meters, s.relativeAltitude.meters)
                    delay(250.milliseconds)
                }
            }
            val serving = launch { op.serve() }

            withTimeout(30.seconds) { control.state.first { it.phase == ControlPhase.Ready } }
            val commands = mutableListOf<Pair<Duration, ControlCommand<SurveyPlan>>>()
            fun issue(command: ControlCommand<SurveyPlan>) {
                if (control.command(command) is CommandOutcome.Accepted) commands += now() to command
            }
            issue(ControlCommand.Build(control.nextEventId(), plan(v)))
            issue(ControlCommand.Start(control.nextEventId()))
            // Two or three pauses (each resumed) at random times; in half the runs an abort among them that ends the run.
            val pauses = rnd.nextInt(2, 4)
            val abortAfter = if (rnd.nextBoolean()) rnd.nextInt(0, pauses + 1) else null
            for (k in 0..pauses) {
                if (abortAfter == k) {
                    delay(rnd.nextInt(5, 40).seconds)
                    issue(ControlCommand.Abort(control.nextEventId()))
                    break
                }
                if (k == pauses) break
                delay(rnd.nextInt(5, 40).seconds)
                issue(ControlCommand.Pause(control.nextEventId()))
                delay(rnd.nextInt(3, 30).seconds) // a pause under ~9 s ends while it still brakes: not checked for holding
                issue(ControlCommand.Resume(control.nextEventId()))
            }
            // The flight ends (done, or stopped by the abort) and the vehicle lands.
            withTimeout(15.minutes) { op.latest.first { it is ControlReport.Done || it is ControlReport.Stopped } }
            withTimeout(15.minutes) { v.telemetry.landedState.first { it == LandedState.ON_GROUND } }
            // An abort the flight carried out ends aborted; one that came as it landed is answered by "finished".
            val abort = commands.firstOrNull { it.second is ControlCommand.Abort }?.second
            val carriedOut = abort != null && sent.any { (_, r) -> r is ControlReport.Stopped && r.eventId == abort.eventId }
            // The app converges on that outcome: reports are said again until one gets through.
            withTimeout(30.seconds) { control.state.first { if (carriedOut) it.phase is ControlPhase.Aborted else it.phase == ControlPhase.Finished } }
            listOf(serving, relay, watching, sampling).forEach { it.cancel() }

            // Never a state older than the last command: what each command's phase may become.
            for ((at, state) in seen.toList()) {
                val last = commands.lastOrNull { it.first <= at }?.second ?: continue
                (state.eventId >= last.eventId) shouldBe true
                withClue("after $last at $at the app showed $state") {
                    when (last) {
                        // Finished: the pause came as it landed, and the outcome answered it.
                        is ControlCommand.Pause -> (state.phase is ControlPhase.Paused || state.phase is ControlPhase.Aborted || state.phase == ControlPhase.Finished) shouldBe true
                        is ControlCommand.Abort -> if (carriedOut) state.phase.shouldBeInstanceOf<ControlPhase.Aborted>() else (state.phase is ControlPhase.Aborted || state.phase == ControlPhase.Finished) shouldBe true
                        is ControlCommand.Resume, is ControlCommand.Start ->
                            (state.phase is ControlPhase.Executing || state.phase == ControlPhase.Finished || state.phase is ControlPhase.Aborted) shouldBe true
                        else -> Unit
                    }
                }
            }
            // A pause the flight applied holds where it is, at its altitude (after braking), until the next command.
            val points = track.toList()
            for ((i, command) in commands.withIndex()) {
                val pause = command.second as? ControlCommand.Pause ?: continue
                val holding = sent.firstOrNull { (_, r) -> r is ControlReport.Holding && r.eventId == pause.eventId }?.first ?: continue
                val until = commands.getOrNull(i + 1)?.first ?: continue
                val held = points.filter { it.at in (holding + 8.seconds)..until }
                if (held.size < 4) continue
                withClue("pause ${pause.eventId} held from $holding to $until") {
                    val (n0, e0) = held.first().north to held.first().east
                    held.maxOf { hypot(it.north - n0, it.east - e0) } shouldBeLessThan 2.0
                    (held.maxOf { it.height } - held.minOf { it.height }) shouldBeLessThan 1.0
                }
                checked.pauses++
            }
            // An abort never descends before it is over home.
            commands.firstOrNull { it.second is ControlCommand.Abort && carriedOut }?.let { (at, _) ->
                val after = points.filter { it.at >= at }
                val overHome = after.firstOrNull { hypot(it.north, it.east) < 3.0 }?.at ?: after.last().at
                val before = after.filter { it.at <= overHome }
                before.shouldNotBeEmpty()
                withClue("abort at $at, over home at $overHome") {
                    before.minOf { it.height } shouldBeGreaterThan before.first().height - 1.0
                }
                checked.aborts++
            }
            v.telemetry.landedState.value shouldBe LandedState.ON_GROUND
            hypot(points.last().north, points.last().east) shouldBeLessThan 3.0
        }
    }
}
