package pod.mavlink.vehicle

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import pod.mavlink.protocol.Step
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.TimeMark

/** Who a vehicle-side machine answers: the system and component a message came from. */
public data class Asker(
    /** The sender's MAVLink system id. */
    public val systemId: Int,
    /** The sender's MAVLink component id. */
    public val componentId: Int,
)

/**
 * Serves [machine] in this scope, the vehicle side's twin of the ground side's one driver
 * (`MavlinkVehicle.run`): [Serving.receive] feeds it each message in place and sends its replies
 * to the sender; its timer runs as a coroutine of this scope. Time is read from [origin] (a mark
 * on the vehicle's `Timebase` clock; the machine's nanoseconds count from it) and waited with this
 * scope's dispatcher, which must follow the same clock: under a test scheduler the machine serves
 * in virtual time.
 *
 * The scope must run one coroutine at a time (a vehicle's single-threaded view of its dispatcher)
 * and [Serving.receive] must be called from it: the machine needs no lock then. Cancelling the
 * scope stops the timer; the machine keeps its state, and a new [serve] drives it
 * again from the next message.
 */
public fun <I, O> CoroutineScope.serve(
    machine: VehicleMachine<I, O>,
    origin: TimeMark,
    send: suspend (message: O, to: Asker) -> Unit,
): Serving<I, O> = Serving(machine, this, origin, send)

/** A [VehicleMachine] being served (see [serve]). */
public class Serving<in I, O> internal constructor(
    private val machine: VehicleMachine<I, O>,
    private val scope: CoroutineScope,
    private val origin: TimeMark,
    private val send: suspend (message: O, to: Asker) -> Unit,
) {
    /** Who spoke last: the timer's messages go there. */
    private var asker: Asker? = null

    /** When the machine last asked to be woken ([Step.NEVER]: not at all). */
    private var wanted = Step.NEVER

    private var timer: Job? = null

    /** The wake time [timer] waits for. */
    private var timerAt = Step.NEVER

    /**
     * Feeds [message] from [from] to the machine, sends its replies to [from], in order, and moves
     * the timer where the machine asked.
     */
    public suspend fun receive(message: I, from: Asker) {
        val step = machine.onMessage(message, now())
        want(step.wakeAt)
        for (reply in step.send) send(reply, from)
        asker = from
        schedule()
    }

    private fun want(wakeAt: Long) {
        if (wakeAt != Step.KEEP) wanted = wakeAt
    }

    /**
     * Keeps one timer at the machine's wake time. A wake time that did not change keeps its timer:
     * re-arming on every incoming message could cancel a timer in the middle of sending its
     * messages, and a ground station that keeps talking would then never hear them.
     */
    private fun schedule() {
        val at = wanted
        if (at == timerAt && timer?.isActive == true) return
        timer?.cancel()
        timerAt = at
        if (at == Step.NEVER) return
        timer = scope.launch {
            delay((at - now()).coerceAtLeast(0).nanoseconds)
            val to = asker ?: return@launch
            withContext(NonCancellable) {
                val step = machine.onTimer(now())
                want(step.wakeAt)
                for (message in step.send) send(message, to)
            }
            timerAt = Step.NEVER
            schedule()
        }
    }

    private fun now(): Long = origin.elapsedNow().inWholeNanoseconds
}
