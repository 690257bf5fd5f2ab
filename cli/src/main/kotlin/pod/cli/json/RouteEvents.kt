package pod.cli.json

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable

/**
 * `pod route`: what one link counted so far, printed for every link every `--every` and when the
 * router stops ([final] true). [port] is the link's local port; counts are frames since it started.
 */
@Serializable @SerialName("route")
public data class RouteSummary(
    val address: String,
    val port: Int,
    val peers: Int,
    val received: Long,
    val forwarded: Long,
    val unrouted: Long,
    @SerialName("bad_crc") val badCrc: Long,
    @SerialName("evicted_peers") val evictedPeers: Long,
    @SerialName("send_drops") val sendDrops: Long,
    val error: String?,
    val final: Boolean,
) : Event
