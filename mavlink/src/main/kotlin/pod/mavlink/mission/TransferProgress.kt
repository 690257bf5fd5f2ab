package pod.mavlink.mission

/** Items done of a transfer's total. */
public data class TransferProgress(
    /** Items sent (upload) or received (download) so far. */
    public val done: Int,
    /** Items in the transfer. */
    public val total: Int,
    /** The list a download received, on its last progress only; null otherwise (and for uploads). */
    public val items: List<MissionItem>? = null,
    /**
     * Why the transfer is waiting before it can start, when it is: the vehicle refused it for now
     * (see [TransferTiming.deniedRetry]). Null otherwise.
     */
    public val waiting: String? = null,
)
