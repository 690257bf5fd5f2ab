package pod.mavlink.mission

import java.util.PriorityQueue
import kotlin.random.Random

/** Faults of a [VirtualLink] direction: probabilities and a delay range in virtual milliseconds. */
internal data class Faults(
    val drop: Double = 0.0,
    val duplicate: Double = 0.0,
    val minDelayMs: Long = 5,
    val maxDelayMs: Long = 5,
    /** Probability that a message is held back 50..300 ms, arriving long after later ones. */
    val hold: Double = 0.0,
)

/**
 * A ground-station machine and a [MissionServer] joined by a lossy link in virtual time: a
 * discrete-event loop, so thousands of transfers with loss, duplication and reordering (delay
 * jitter) run in milliseconds and are reproducible from a seed.
 */
internal class VirtualLink(
    private val server: MissionServer,
    private val up: Faults,
    private val down: Faults,
    seed: Long,
    /** Messages lost on purpose, whatever the faults say ([toVehicle]: on the way up). */
    private val lose: (message: MissionMessage, toVehicle: Boolean) -> Boolean = { _, _ -> false },
) {
    private val random = Random(seed)
    private var now = 0L // nanoseconds
    private var order = 0L
    private class Event(val at: Long, val order: Long, val toVehicle: Boolean, val message: MissionMessage?)
    private val queue = PriorityQueue<Event>(compareBy<Event>({ it.at }, { it.order }))
    private var gcsTimerAt = Long.MAX_VALUE

    var messagesSent = 0
        private set
    val elapsedMs: Long get() = now / 1_000_000

    /** Runs a ground-station machine to its outcome, or returns null if it is still going after [limitMs] virtual ms. */
    fun <T> run(
        start: () -> MissionStep<T>,
        onMessage: (MissionMessage, Long) -> MissionStep<T>,
        onTimeout: (Long) -> MissionStep<T>,
        limitMs: Long = 3 * 60 * 60_000, // generous: what is tested is that every transfer ends
    ): TransferOutcome<T>? {
        queue.clear()
        gcsTimerAt = Long.MAX_VALUE
        var step = start()
        while (true) {
            apply(step)?.let { return it }
            val serverAt = server.nextTimeoutAt ?: Long.MAX_VALUE
            val eventAt = queue.peek()?.at ?: Long.MAX_VALUE
            val next = minOf(serverAt, eventAt, gcsTimerAt)
            if (next == Long.MAX_VALUE || next > limitMs * 1_000_000) return null
            now = next
            step = when (next) {
                eventAt -> {
                    val event = queue.poll()
                    if (event.toVehicle) {
                        toVehicle(event.message!!)
                        MissionStep.NOTHING
                    } else {
                        onMessage(event.message!!, now)
                    }
                }
                serverAt -> {
                    vehicleTimer()
                    MissionStep.NOTHING
                }
                else -> {
                    gcsTimerAt = Long.MAX_VALUE
                    onTimeout(now)
                }
            }
        }
    }

    /**
     * Sends [messages] to the vehicle as a ground station that has stopped listening would (what a
     * cancelled transfer does), and lets the link run until nothing is in flight and the vehicle
     * has no timer set, or [limitMs] of virtual time passed. Returns whether it went quiet.
     */
    fun sendAndSettle(messages: List<MissionMessage>, limitMs: Long = 60_000): Boolean {
        gcsTimerAt = Long.MAX_VALUE
        messages.forEach { send(it, toVehicle = true) }
        val until = now + limitMs * 1_000_000
        while (true) {
            val serverAt = server.nextTimeoutAt ?: Long.MAX_VALUE
            val eventAt = queue.peek()?.at ?: Long.MAX_VALUE
            val next = minOf(serverAt, eventAt)
            if (next == Long.MAX_VALUE) return true
            if (next > until) return false
            now = next
            if (next == eventAt) {
                val event = queue.poll()
                if (event.toVehicle) toVehicle(event.message!!) // what comes back for the ground station is lost with it
            } else {
                vehicleTimer()
            }
        }
    }

    private fun toVehicle(message: MissionMessage) = server.onMessage(message, now).forEach { send(it, toVehicle = false) }

    private fun vehicleTimer() = server.onTimeout(now).forEach { send(it, toVehicle = false) }

    private fun <T> apply(step: MissionStep<T>): TransferOutcome<T>? {
        step.send.forEach { send(it, toVehicle = true) }
        when (step.timerNanos) {
            MissionStep.KEEP_TIMER -> Unit
            MissionStep.NO_TIMER -> gcsTimerAt = Long.MAX_VALUE
            else -> gcsTimerAt = now + step.timerNanos
        }
        return step.outcome
    }

    private fun send(message: MissionMessage, toVehicle: Boolean) {
        messagesSent++
        if (lose(message, toVehicle)) return
        val faults = if (toVehicle) up else down
        if (random.nextDouble() < faults.drop) return
        val copies = if (random.nextDouble() < faults.duplicate) 2 else 1
        repeat(copies) {
            var delayMs = if (faults.maxDelayMs > faults.minDelayMs) random.nextLong(faults.minDelayMs, faults.maxDelayMs + 1) else faults.minDelayMs
            if (random.nextDouble() < faults.hold) delayMs += random.nextLong(50, 301)
            queue += Event(now + delayMs * 1_000_000, order++, toVehicle, message)
        }
    }
}
