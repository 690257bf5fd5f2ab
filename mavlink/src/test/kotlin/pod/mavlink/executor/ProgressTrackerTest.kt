package pod.mavlink.executor

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.checkAll
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.mission.SpeedKind
import pod.core.platform.MissionEvent
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.core.units.mps
import pod.mavlink.executor.ProgressTracker.Output
import pod.mavlink.plan.MissionFlavor
import pod.mavlink.plan.MissionPlanner

private val home = Location(41.178_046, -8.595_786, 120.m)
private val at = home.copy(altitude = 20.m)

/** Every step started then done, in order, then Completed. */
private fun inOrder(steps: Int): List<MissionEvent> =
    (0 until steps).flatMap { listOf(MissionEvent.StepStarted(it), MissionEvent.StepDone(it)) } + MissionEvent.Completed

private fun List<Output>.events() = filterIsInstance<Output.Event>().map { it.event }

class ProgressTrackerTest : StringSpec({
    val steps = listOf(
        MissionStep.TakeOff(at, 0.deg), MissionStep.ChangeSpeed(SpeedKind.GROUND, 4.mps), MissionStep.Waypoint(at.offset(20.m, 0.m)),
        MissionStep.Waypoint(at.offset(20.m, 20.m)), MissionStep.StartCapture(1, 0.deg.let { kotlin.time.Duration.ZERO }), MissionStep.ReturnHome,
    )

    "reports each step started and done once, in order, however the vehicle's reports are skipped, repeated or reordered" {
        val plan = MissionPlanner.plan(Mission("m", null, steps), MissionFlavor.ARDUCOPTER, home)
        checkAll(300, Arb.list(Arb.int(0..plan.items.size), 0..30)) { noise ->
            val tracker = ProgressTracker(plan)
            val events = ArrayList<MissionEvent>()
            // A random walk of reports, then the truth: every item current in turn and every NAV item reached.
            noise.forEachIndexed { i, seq -> events += (if (i % 2 == 0) tracker.onCurrent(seq.coerceAtMost(1)) else tracker.onReached(-1)).events() }
            for (seq in 1 until plan.items.size) {
                events += tracker.onCurrent(seq).events()
                if (plan.items[seq].command < 95) events += tracker.onReached(seq).events()
            }
            tracker.allDone shouldBe true
            events += tracker.finish().events()
            events shouldBe inOrder(steps.size)
        }
    }

    "a reached item ends every step up to it, and the DO items after the last navigation item with it" {
        val plan = MissionPlanner.plan(Mission("m", null, steps), MissionFlavor.ARDUCOPTER, home)
        val tracker = ProgressTracker(plan)
        tracker.onReached(plan.items.size - 1).events() shouldBe inOrder(steps.size).dropLast(1)
    }

    "a step sent as a command is due when the next item becomes current, and the steps after it wait for it" {
        val px4 = listOf(MissionStep.TakeOff(at, 0.deg), MissionStep.ChangeSpeed(SpeedKind.CLIMB, 2.mps), MissionStep.Waypoint(at), MissionStep.ChangeSpeed(SpeedKind.DESCENT, 1.mps))
        val plan = MissionPlanner.plan(Mission("m", null, px4), MissionFlavor.PX4, home)
        val tracker = ProgressTracker(plan)
        tracker.onCurrent(0).events() shouldBe listOf(MissionEvent.StepStarted(0))
        val due = tracker.onReached(1)
        due.events() shouldBe listOf(MissionEvent.StepDone(0), MissionEvent.StepStarted(1))
        (due.last() as Output.Send).step shouldBe 1
        val after = tracker.commandsSent(1)
        after.events() shouldBe listOf(MissionEvent.StepDone(1), MissionEvent.StepStarted(2), MissionEvent.StepDone(2), MissionEvent.StepStarted(3))
        (after.last() as Output.Send).commands.single().param1 shouldBe 3f
        tracker.commandsSent(3).events() shouldBe listOf(MissionEvent.StepDone(3))
        tracker.allDone shouldBe true
    }

    "an ArduCopter landing: the item before it reached (its MISSION_CURRENT lost) puts the vehicle on the landing, and the reset to item 1 after the disarm is not a step back" {
        val landing = listOf(MissionStep.TakeOff(at, 0.deg), MissionStep.Waypoint(at.offset(20.m, 0.m)), MissionStep.Land(home))
        val plan = MissionPlanner.plan(Mission("m", null, landing), MissionFlavor.ARDUCOPTER, home)
        val tracker = ProgressTracker(plan)
        val land = plan.items.indexOfLast { it.command == 21 }
        val events = ArrayList<MissionEvent>()
        events += tracker.onCurrent(1).events()
        // Only what ArduCopter sends unasked: each item before the landing reached; nothing for the landing.
        for (seq in 1 until land) events += tracker.onReached(seq).events()
        tracker.currentItem shouldBe land
        (tracker.currentItem >= tracker.lastStepStart) shouldBe true
        events += tracker.onCurrent(1).events()
        tracker.currentItem shouldBe land
        tracker.currentStep shouldBe 2
        events shouldBe inOrder(2).dropLast(1) + MissionEvent.StepStarted(2)
    }

    "an ArduCopter landing seen through MISSION_CURRENT alone (every MISSION_ITEM_REACHED lost): on the landing, then back to 1, still on the landing" {
        val landing = listOf(MissionStep.TakeOff(at, 0.deg), MissionStep.Waypoint(at.offset(20.m, 0.m)), MissionStep.Land(home))
        val plan = MissionPlanner.plan(Mission("m", null, landing), MissionFlavor.ARDUCOPTER, home)
        val tracker = ProgressTracker(plan)
        val land = plan.items.indexOfLast { it.command == 21 }
        val events = ArrayList<MissionEvent>()
        for (seq in 1..land) events += tracker.onCurrent(seq).events()
        events += tracker.onCurrent(1).events()
        tracker.currentItem shouldBe land
        tracker.currentStep shouldBe 2
        events shouldBe inOrder(2).dropLast(1) + MissionEvent.StepStarted(2)
    }

    "finish ends the steps not yet reported, then completes, once" {
        val loiter = listOf(MissionStep.TakeOff(at, 0.deg), MissionStep.Loiter(at, 0.m, pod.core.mission.LoiterDuration.Unlimited))
        val tracker = ProgressTracker(MissionPlanner.plan(Mission("m", null, loiter), MissionFlavor.ARDUCOPTER, home))
        tracker.onCurrent(2).events() shouldBe listOf(MissionEvent.StepStarted(0), MissionEvent.StepDone(0), MissionEvent.StepStarted(1))
        tracker.finish().events() shouldBe listOf(MissionEvent.StepDone(1), MissionEvent.Completed)
        tracker.finish() shouldBe emptyList()
    }
})
