package pod.sim.fault

/**
 * What happened to the datagrams of one direction so far. Copies are counted, so once nothing is
 * held back or in flight, `sent - dropped + duplicated == delivered + discarded`.
 */
public data class LinkCounters(
    /** Datagrams that entered the faulty link. */
    public val sent: Long = 0,
    /** Datagrams lost on purpose. */
    public val dropped: Long = 0,
    /** Extra copies made. */
    public val duplicated: Long = 0,
    /** Datagrams held back and overtaken by at least one later datagram. */
    public val reordered: Long = 0,
    /** Datagrams with one byte changed. */
    public val corrupted: Long = 0,
    /**
     * Copies that came out: handed back for delivery by a [FaultModel], or written to the far
     * side's socket by a [LossyRelay].
     */
    public val delivered: Long = 0,
    /**
     * Copies a [LossyRelay] could not forward: its queues were full, or the far side had no peer
     * to send to yet. Always 0 for a bare [FaultModel].
     */
    public val discarded: Long = 0,
)
