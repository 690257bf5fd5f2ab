package pod.mavlink.command

import pod.mavlink.protocol.Outcome
import pod.mavlink.protocol.Step
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.longs.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

private const val ARM = 400
private val MS = 1.milliseconds.inWholeNanoseconds

private fun transaction(timing: CommandTiming = CommandTiming()) =
    CommandTransaction(VehicleCommand(ARM, param1 = 1f), timing, CommandRoundTrip(timing))

/** The confirmation number a step sends the command with, or -1 when it sends nothing. */
private val Step<Int, CommandReply>.confirmation: Int get() = send.singleOrNull() ?: -1

/** The error a step ended with. */
private val Step<Int, CommandReply>.error: CommandException get() = (outcome as Outcome.Failed).error as CommandException

private fun reply(result: CommandResult, progress: Int? = null, command: Int = ARM) = CommandReply(command, result.mavValue, progress)

class CommandTransactionTest : StringSpec({

    "an accepted command is sent once and ends with the vehicle's reply" {
        val t = transaction()
        t.start(0).confirmation shouldBe 0
        val end = t.onReply(reply(CommandResult.ACCEPTED), 3 * MS)
        end.outcome.shouldBeInstanceOf<Outcome.Done<CommandReply>>()
        end.confirmation shouldBe -1
        t.onReply(reply(CommandResult.DENIED), 4 * MS).outcome shouldBe null // a late duplicate changes nothing
    }

    "without an answer it resends with confirmation counting up, waits longer each time, and fails when silence reaches the timeout" {
        val timing = CommandTiming()
        val t = transaction(timing)
        var step = t.start(0)
        val confirmations = mutableListOf(step.confirmation)
        val waits = mutableListOf<Long>()
        var now = 0L
        while (step.outcome == null) {
            waits += step.wakeAt - now
            now = step.wakeAt
            step = t.onTimer(now)
            if (step.confirmation >= 0) confirmations += step.confirmation
        }
        confirmations shouldContainExactly confirmations.indices.toList()
        now shouldBe timing.timeout.inWholeNanoseconds
        waits.first() shouldBe timing.initialAttemptTimeout.inWholeNanoseconds
        waits.dropLast(1).zipWithNext().all { (a, b) -> b >= a } shouldBe true
        waits.max() shouldBeLessThanOrEqual timing.maxAttemptTimeout.inWholeNanoseconds
        step.error.shouldBeInstanceOf<CommandTimeout>().attempts shouldBe confirmations.size
    }

    "while the vehicle keeps talking a lost command goes again after the same timeout, then backs off; silence backs off at once" {
        val timing = CommandTiming(quickResends = 3)
        fun waits(talking: Boolean): List<Long> {
            val t = transaction(timing)
            var step = t.start(0)
            val waits = mutableListOf<Long>()
            var now = 0L
            while (step.outcome == null && waits.size < 6) {
                waits += step.wakeAt - now
                now = step.wakeAt
                step = t.onTimer(now, vehicleTalking = talking)
            }
            return waits
        }
        val base = timing.initialAttemptTimeout.inWholeNanoseconds
        waits(talking = true) shouldBe listOf(base, base, base, base, base * 3 / 2, base * 9 / 4).map { it.coerceAtMost(timing.maxAttemptTimeout.inWholeNanoseconds) }
        waits(talking = false) shouldBe listOf(base, base * 3 / 2, base * 9 / 4, base * 27 / 8, base * 81 / 16, base * 243 / 32).map { it.coerceAtMost(timing.maxAttemptTimeout.inWholeNanoseconds) }
    }

    "DENIED, UNSUPPORTED and FAILED end the command with the vehicle's texts, from before the refusal and just after it" {
        for (result in listOf(CommandResult.DENIED, CommandResult.UNSUPPORTED, CommandResult.FAILED, CommandResult.CANCELLED)) {
            val t = transaction()
            t.start(0)
            t.onMessage(CommandInput.Text("Arm: Battery below minimum\t"), MS / 2)
            val listening = t.onReply(reply(result), MS)
            listening.outcome shouldBe null
            listening.send shouldBe emptyList()
            // A line queued behind the ack extends the wait; a repeated line counts once.
            val later = t.onMessage(CommandInput.Text("Arm: Battery below minimum"), 100 * MS)
            later.wakeAt shouldBe 250 * MS
            val error = t.onTimer(later.wakeAt).error
            error.shouldBeInstanceOf<CommandRejected>().result shouldBe result
            error.message shouldBe "MAV_CMD_COMPONENT_ARM_DISARM was ${result.name}: Arm: Battery below minimum"
        }
    }

    "IN_PROGRESS stops resending, reports progress, and waits for the final result" {
        val timing = CommandTiming(inProgressTimeout = 5.seconds)
        val t = transaction(timing)
        t.start(0)
        val working = t.onReply(reply(CommandResult.IN_PROGRESS, 20), 2 * MS)
        working.confirmation shouldBe -1
        t.progress shouldBe 20
        working.wakeAt shouldBe 2 * MS + 5.seconds.inWholeNanoseconds
        t.onReply(reply(CommandResult.IN_PROGRESS, 70), 3.seconds.inWholeNanoseconds)
        t.progress shouldBe 70
        t.onReply(reply(CommandResult.ACCEPTED), 4.seconds.inWholeNanoseconds).outcome.shouldBeInstanceOf<Outcome.Done<CommandReply>>()

        val stalled = transaction(timing)
        stalled.start(0)
        val wait = stalled.onReply(reply(CommandResult.IN_PROGRESS, 10), MS)
        val end = stalled.onTimer(wait.wakeAt)
        end.error.shouldBeInstanceOf<CommandTimeout>().waitingFor shouldBe "a final result after IN_PROGRESS (10 %)"
    }

    "TEMPORARILY_REJECTED is retried after the retry delay, and fails once it has lasted the budget" {
        val timing = CommandTiming(retryDelay = 500.milliseconds, temporarilyRejectedFor = 2.seconds)
        val t = transaction(timing)
        t.start(0)
        var now = MS
        var step = t.onReply(reply(CommandResult.TEMPORARILY_REJECTED), now)
        var resends = 0
        while (step.wakeAt == now + 500 * MS) {
            now = step.wakeAt
            t.onTimer(now).confirmation shouldBe ++resends
            now += MS
            step = t.onReply(reply(CommandResult.TEMPORARILY_REJECTED), now)
        }
        resends shouldBe 3
        t.onTimer(step.wakeAt).error.shouldBeInstanceOf<CommandRejected>().result shouldBe CommandResult.TEMPORARILY_REJECTED

        val later = transaction(timing)
        later.start(0)
        val retry = later.onReply(reply(CommandResult.TEMPORARILY_REJECTED), MS)
        later.onTimer(retry.wakeAt).confirmation shouldBe 1
        later.onReply(reply(CommandResult.ACCEPTED), retry.wakeAt + MS).outcome.shouldBeInstanceOf<Outcome.Done<CommandReply>>()
    }

    "answers to another command are ignored" {
        val t = transaction()
        val first = t.start(0)
        val ignored = t.onReply(reply(CommandResult.DENIED, command = 176), MS)
        ignored.send shouldBe emptyList()
        ignored.wakeAt shouldBe Step.KEEP
        first.wakeAt shouldBe CommandTiming().initialAttemptTimeout.inWholeNanoseconds
        t.isDone shouldBe false
    }

    "the attempt timeout follows the measured round trip within its bounds" {
        val timing = CommandTiming()
        val rtt = CommandRoundTrip(timing)
        rtt.attemptTimeoutNanos shouldBe timing.initialAttemptTimeout.inWholeNanoseconds
        repeat(20) { rtt.sample(2 * MS) }
        rtt.attemptTimeoutNanos shouldBe timing.minAttemptTimeout.inWholeNanoseconds
        repeat(50) { rtt.sample(200 * MS) }
        (rtt.attemptTimeoutNanos in 200 * MS..timing.maxAttemptTimeout.inWholeNanoseconds) shouldBe true
    }

    "bad timings are refused with the argument named" {
        shouldThrow<IllegalArgumentException> { CommandTiming(minAttemptTimeout = 0.seconds) }.message shouldBe "minAttemptTimeout must be > 0, was 0s"
        shouldThrow<IllegalArgumentException> { CommandTiming(timeout = 100.milliseconds) }.message shouldBe "timeout must be ≥ maxAttemptTimeout (1s), was 100ms"
    }
})
