package pod.mavlink.mission

/**
 * What a protocol machine asks of its driver after one input: messages to send (in order), the
 * timer to (re)arm — or [NO_TIMER] to stop it — and, once the transfer has ended, its [outcome].
 */
internal class MissionStep<out T>(
    val send: List<MissionMessage> = emptyList(),
    val timerNanos: Long = KEEP_TIMER,
    val outcome: TransferOutcome<T>? = null,
) {
    companion object {
        /** Leave the timer as it is. */
        const val KEEP_TIMER = -1L

        /** Stop the timer. */
        const val NO_TIMER = -2L

        val NOTHING = MissionStep<Nothing>()
    }
}

/** How a transfer ended. */
internal sealed class TransferOutcome<out T> {
    data class Done<T>(val value: T) : TransferOutcome<T>()
    data class Failed(val error: MissionException) : TransferOutcome<Nothing>()

    /** Upload only: every item went out but the final ACK never came; the driver checks by downloading. */
    object AckMissing : TransferOutcome<Nothing>()
}

/** Items done of a transfer's total. */
public data class TransferProgress(
    /** Items sent (upload) or received (download) so far. */
    public val done: Int,
    /** Items in the transfer. */
    public val total: Int,
)
