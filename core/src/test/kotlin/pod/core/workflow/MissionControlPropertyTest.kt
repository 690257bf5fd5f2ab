package pod.core.workflow

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import kotlin.random.Random

/**
 * Mission control between an app and a flight that hears its commands late and whose reports
 * arrive late, out of order, twice or never: whatever the timing, the state the app shows never
 * goes back to one older than its last command, and once the link is quiet it shows what the
 * flight is doing.
 */
class MissionControlPropertyTest : StringSpec({

    "a report from before a pause does not flip the app back to executing while the pause travels" {
        val app = MissionControl<String>(ControlState(ControlPhase.Ready, null, 0))
        app.command(ControlCommand.Build(app.nextEventId(), "survey")).shouldBeInstanceOf<CommandOutcome.Accepted<String>>()
        app.command(ControlCommand.Start(app.nextEventId())).shouldBeInstanceOf<CommandOutcome.Accepted<String>>()
        app.report(ControlReport.Flying(2, Pass.FORWARD, 3)) shouldBe true
        val pause = app.nextEventId()
        app.command(ControlCommand.Pause(pause))
        app.state.value.phase shouldBe ControlPhase.Paused(Pass.FORWARD, 3)
        app.report(ControlReport.Flying(2, Pass.FORWARD, 4)) shouldBe false // sent before the pause arrived
        app.state.value.phase shouldBe ControlPhase.Paused(Pass.FORWARD, 3)
        app.report(ControlReport.Holding(pause, Pass.FORWARD, 4)) shouldBe true
        app.state.value shouldBe ControlState(ControlPhase.Paused(Pass.FORWARD, 4), "survey", pause)
    }

    "commands a state does not allow are refused with a reason and change nothing" {
        val app = MissionControl<String>(ControlState(ControlPhase.Ready, null, 0))
        val refused = app.command(ControlCommand.Pause(app.nextEventId())).shouldBeInstanceOf<CommandOutcome.Refused>()
        refused.reason shouldContain "pause: not possible while ready with no path"
        app.command(ControlCommand.Start(app.nextEventId())).shouldBeInstanceOf<CommandOutcome.Refused>().reason shouldContain "start"
        app.state.value.phase shouldBe ControlPhase.Ready
        app.command(ControlCommand.Build(1, "late")).shouldBeInstanceOf<CommandOutcome.Accepted<String>>()
        app.command(ControlCommand.CancelPath(1)).shouldBeInstanceOf<CommandOutcome.Refused>().reason shouldContain "not newer"
    }

    "a controller attached to a flight in progress starts from what the flight reports" {
        val app = MissionControl<String>(ControlState(ControlPhase.Executing(Pass.BACKWARD, 2), null, 41))
        app.nextEventId() shouldBe 42
        app.command(ControlCommand.Pause(42)).shouldBeInstanceOf<CommandOutcome.Accepted<String>>().state.phase shouldBe ControlPhase.Paused(Pass.BACKWARD, 2)
    }

    "under random command timing and a lossy, reordering report link the app never shows a state older than its last command, and ends showing the flight's" {
        checkAll(PropTestConfig(iterations = 500, seed = 15), Arb.long()) { seed ->
            Session(Random(seed)).run()
        }
    }
}) {
    /** The flight side: applies commands in the order sent, reports what it does. */
    private class Flight {
        var state = ControlState<String>(ControlPhase.Ready, null, 0)
        private var legs = 0

        fun hear(command: ControlCommand<String>) {
            state = when (val outcome = ControlRules.apply(state, command)) {
                is CommandOutcome.Accepted -> outcome.state
                // Refused here (the flight moved on): it still answers with the command's id.
                is CommandOutcome.Refused -> state.copy(eventId = command.eventId)
            }
        }

        /** One step of flying: the waypoint moves on; the forward pass hands over to the backward one, which ends. */
        fun fly(random: Random) {
            val phase = state.phase as? ControlPhase.Executing ?: return
            if (random.nextInt(4) != 0) return
            legs++
            val next = (phase.waypoint ?: -1) + 1
            state = state.copy(
                phase = when {
                    next < 5 -> phase.copy(waypoint = next)
                    phase.pass == Pass.FORWARD -> ControlPhase.Executing(Pass.BACKWARD, 0)
                    else -> ControlPhase.Finished
                },
            )
        }

        fun report(): ControlReport = when (val p = state.phase) {
            is ControlPhase.Executing -> ControlReport.Flying(state.eventId, p.pass, p.waypoint)
            is ControlPhase.Paused -> ControlReport.Holding(state.eventId, p.pass, p.waypoint)
            ControlPhase.Finished -> ControlReport.Done(state.eventId)
            is ControlPhase.Aborted -> ControlReport.Stopped(state.eventId, p.reason)
            else -> ControlReport.Vehicle(state.eventId, ready = true)
        }
    }

    private class Session(private val random: Random) {
        private val app = MissionControl<String>(ControlState(ControlPhase.Ready, null, 0))
        private val flight = Flight()
        private val commands = ArrayDeque<Pair<Int, ControlCommand<String>>>() // (arrival step, command), in order
        private val reports = ArrayList<Pair<Int, ControlReport>>()

        fun run() {
            var lastCommand = 0L
            var shown = app.state.value.eventId
            for (step in 0 until 400) {
                if (random.nextInt(6) == 0) send(step)?.let { lastCommand = it }
                while (commands.isNotEmpty() && commands.first().first <= step) flight.hear(commands.removeFirst().second)
                flight.fly(random)
                // Reports: lost (30 %), late by up to 12 steps (so out of order), sometimes twice.
                if (random.nextInt(2) == 0) repeat(if (random.nextInt(10) == 0) 2 else 1) {
                    if (random.nextDouble() >= 0.3) reports += (step + random.nextInt(13)) to flight.report()
                }
                reports.filter { it.first <= step }.shuffled(random).forEach { app.report(it.second) }
                reports.removeAll { it.first <= step }

                val now = app.state.value.eventId
                check(now >= shown) { "the app went back from event $shown to $now" }
                check(now >= lastCommand) { "the app shows event $now, older than its last command $lastCommand" }
                shown = now
            }
            // The link goes quiet: every command arrives, the flight's next report gets through.
            while (commands.isNotEmpty()) flight.hear(commands.removeFirst().second)
            reports.forEach { app.report(it.second) }
            app.report(flight.report())
            check(app.state.value.phase == flight.state.phase) { "the app shows ${app.state.value.phase}, the flight is ${flight.state.phase}" }
        }

        /** Presses a button the app's state enables (or, one time in ten, any button), and sends it. */
        private fun send(step: Int): Long? {
            val id = app.nextEventId()
            val command: ControlCommand<String> = when (random.nextInt(6)) {
                0 -> ControlCommand.Build(id, "plan $id")
                1 -> ControlCommand.CancelPath(id)
                2 -> ControlCommand.Start(id)
                3 -> ControlCommand.Pause(id)
                4 -> ControlCommand.Resume(id)
                else -> ControlCommand.Abort(id)
            }
            if (app.command(command) !is CommandOutcome.Accepted<*>) return null
            val arrival = maxOf(step + random.nextInt(1, 9), commands.lastOrNull()?.first ?: 0)
            commands.addLast(arrival to command)
            return id
        }
    }
}
