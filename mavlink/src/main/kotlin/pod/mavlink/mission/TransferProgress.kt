package pod.mavlink.mission

/** Items done of a transfer's total. */
public data class TransferProgress(
    /** Items sent (upload) or received (download) so far. */
    public val done: Int,
    /** Items in the transfer. */
    public val total: Int,
    /** The list a download received, on its last progress only; null otherwise (and for uploads). */
    public val items: List<MissionItem>? = null,
)
