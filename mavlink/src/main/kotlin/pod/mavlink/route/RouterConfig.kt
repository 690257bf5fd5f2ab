package pod.mavlink.route

import pod.core.time.Timebase
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** How a [MavlinkRouter] bounds what it remembers. */
public data class RouterConfig(
    /**
     * Most peers one listening (`udpin`) link keeps routes and a frame decoder for; beyond it the
     * one heard least recently is forgotten (counted in [RouteLinkStats.evictedPeers]), so a flood
     * of datagrams from spoofed addresses cannot grow memory without limit.
     */
    public val maxPeersPerLink: Int = 256,
    /**
     * A peer of a listening link silent this long is forgotten with its routes: a ground station
     * that quit (every `pod` command comes from a new port) stops receiving broadcasts. Every
     * MAVLink node sends HEARTBEAT at 1 Hz, so a live one is heard well within it.
     */
    public val forgetPeersAfter: Duration = 10.seconds,
    /** Frames waiting for a link that cannot send in place (TCP); more are dropped and counted. */
    public val sendQueue: Int = 1024,
    /** The clock peers' silence is measured on and the dispatcher the router's coroutines run on. */
    public val timebase: Timebase = Timebase.System,
) {
    init {
        require(maxPeersPerLink >= 1) { "maxPeersPerLink must be ≥ 1, was $maxPeersPerLink" }
        require(forgetPeersAfter.isPositive()) { "forgetPeersAfter must be > 0, was $forgetPeersAfter" }
        require(sendQueue >= 1) { "sendQueue must be ≥ 1, was $sendQueue" }
    }
}

/** What a [MavlinkRouter] counted on one of its links since it started. */
public data class RouteLinkStats(
    /** The link, as its connection string. */
    public val address: String,
    /** Peers routed to now: every sender heard on a listening link, else the link's one remote. */
    public val peers: Int,
    /** Valid frames heard on this link. */
    public val received: Long,
    /** Frames from other links written to this link (once per peer). */
    public val forwarded: Long,
    /** Frames heard on this link for a target system heard nowhere else: dropped, as mavlink-router does. */
    public val unrouted: Long,
    /** Frames heard on this link with a bad CRC: dropped. */
    public val badCrc: Long,
    /** Peers forgotten to stay within [RouterConfig.maxPeersPerLink]. */
    public val evictedPeers: Long,
    /** Frames for this link dropped because its send queue was full or the link had broken. */
    public val sendDrops: Long,
    /** Why the link stopped, or null while it works. */
    public val error: String?,
)
