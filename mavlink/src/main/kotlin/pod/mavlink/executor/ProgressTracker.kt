package pod.mavlink.executor

import pod.core.platform.MissionEvent
import pod.mavlink.command.VehicleCommand
import pod.mavlink.plan.MissionPlan

/**
 * Follows a vehicle through a [MissionPlan] from what it reports (MISSION_CURRENT and
 * MISSION_ITEM_REACHED) and turns that into mission-step events, each step started and done once
 * and in order, even when reports are skipped or arrive out of order. A pure machine: the
 * executor feeds it and carries out what it returns.
 *
 * A step made of items is done when the vehicle reports its last item reached or its current item
 * has moved past it. Once the last navigation item is reached, the vehicle is past the end: the
 * DO items after it ran with it. A step sent as a command is due when the current item reaches its
 * key; the tracker waits for [commandsSent] before it goes on.
 */
internal class ProgressTracker(private val plan: MissionPlan) {
    /** What the executor must do. */
    sealed interface Output {
        /** Report [event]. */
        data class Event(val event: MissionEvent) : Output

        /** Send [commands] for [step], then call [commandsSent]. */
        data class Send(val step: Int, val commands: List<VehicleCommand>) : Output
    }

    private val stepCount = plan.stepCount
    private val firstSeq = IntArray(stepCount) { -1 }
    private val lastSeq = IntArray(stepCount) { -1 }
    private val keySeq = IntArray(stepCount) { -1 }
    private val lastNavSeq: Int = plan.items.indexOfLast { it.command < NAV_LAST && plan.stepOf(it.seq) != null }
    private var current = -1
    private var reached = -1
    private var startedUpTo = -1
    private var pending: Int? = null
    private var completed = false

    /** Index of the first step not yet done (the step count when all are). */
    var next: Int = 0
        private set

    init {
        for ((seq, step) in plan.stepOfItem) {
            if (firstSeq[step] < 0 || seq < firstSeq[step]) firstSeq[step] = seq
            if (seq > lastSeq[step]) lastSeq[step] = seq
        }
        for (k in plan.keyedCommands) keySeq[k.step] = k.seq
        for (s in 0 until stepCount) require(firstSeq[s] >= 0 || keySeq[s] >= 0) { "step $s has neither items nor commands" }
    }

    /** True once every step is done. */
    val allDone: Boolean get() = next >= stepCount

    /** The step the vehicle is on (started, not done), or null. */
    val currentStep: Int? get() = next.takeIf { it < stepCount && startedUpTo >= it }

    /** The highest item the vehicle reported current. */
    val currentItem: Int get() = current

    /** The seq the last step starts at (its first item, or its command's key). */
    val lastStepStart: Int get() = (stepCount - 1).let { if (firstSeq[it] >= 0) firstSeq[it] else keySeq[it] }

    /**
     * The vehicle reports item [seq] as its current one. Progress only moves forward: a lower item
     * is ignored, whether it is a jump back (DO_JUMP) or ArduCopter resetting its mission to item 1
     * when it disarms after the final landing (ArduCopter/AP_Arming.cpp, AP_Arming_Copter::disarm
     * calls mission.reset()).
     */
    fun onCurrent(seq: Int): List<Output> {
        if (seq > current) current = seq
        return advance()
    }

    /**
     * The vehicle reports item [seq] reached: it has moved on to a later item, so this also stands
     * for a MISSION_CURRENT of at least [seq] + 1 that may have been lost (MISSION_CURRENT is a
     * periodic stream; completion must not hang on one lost message).
     */
    fun onReached(seq: Int): List<Output> {
        if (seq > reached) reached = seq
        if (seq + 1 > current) current = seq + 1
        return advance()
    }

    /** The commands of the due step were accepted. */
    fun commandsSent(step: Int): List<Output> {
        check(pending == step) { "step $step was not waiting for its commands (pending: $pending)" }
        pending = null
        val out = ArrayList<Output>()
        out += Output.Event(MissionEvent.StepDone(step))
        next = step + 1
        out += advance()
        return out
    }

    /**
     * The mission is complete by the executor's rule (landed, loitering at the end): every step
     * not yet reported starts and ends, then Completed. Empty when already completed.
     */
    fun finish(): List<Output> {
        if (completed) return emptyList()
        completed = true
        val out = ArrayList<Output>()
        for (s in next until stepCount) {
            if (startedUpTo < s) out += Output.Event(MissionEvent.StepStarted(s)).also { startedUpTo = s }
            out += Output.Event(MissionEvent.StepDone(s))
        }
        next = stepCount
        pending = null
        out += Output.Event(MissionEvent.Completed)
        return out
    }

    private fun advance(): List<Output> {
        val out = ArrayList<Output>()
        // Past the last navigation item, the vehicle is past the end of the list.
        val at = if (lastNavSeq < 0 || reached >= lastNavSeq) plan.items.size else current
        while (next < stepCount && pending == null && !completed) {
            val s = next
            if (firstSeq[s] >= 0) {
                val done = at > lastSeq[s] || reached >= lastSeq[s]
                val started = done || at >= firstSeq[s] || reached >= firstSeq[s]
                if (started && startedUpTo < s) {
                    out += Output.Event(MissionEvent.StepStarted(s))
                    startedUpTo = s
                }
                if (!done) break
                out += Output.Event(MissionEvent.StepDone(s))
                next++
            } else {
                val key = keySeq[s]
                if (at < key && reached < key - 1) break
                if (startedUpTo < s) {
                    out += Output.Event(MissionEvent.StepStarted(s))
                    startedUpTo = s
                }
                pending = s
                out += Output.Send(s, plan.commandsOf(s).map { it.command })
            }
        }
        return out
    }

    private companion object {
        /** MAV_CMD_NAV_LAST: commands below it are navigation commands. */
        const val NAV_LAST = 95
    }
}
