package pod.mavlink.route

import kotlinx.coroutines.CoroutineScope
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import java.util.concurrent.CopyOnWriteArrayList

/**
 * The routers a [pod.mavlink.GroundStation] feeds ([pod.mavlink.GroundStation.forwardTo]): each
 * frame the station parses from its link is handed to them, with the peer it came from, so the
 * station's socket is read once and its vehicles are also served to other ground stations.
 */
internal class StationForwarding(private val stationLink: MavlinkLink, private val codec: MessageCodec) {
    private val routers = CopyOnWriteArrayList<MavlinkRouter>()

    /** True while any router is fed: the station then hands its frames over. */
    val active: Boolean get() = routers.isNotEmpty()

    /** A frame the station parsed from [peer]; called on its receive path. */
    fun onFrame(peer: LinkPeer, frame: MavFrame) {
        for (router in routers) router.fromStation(peer, frame)
    }

    /** Starts routing between the station's link and [other] in [scope]. */
    fun start(other: MavlinkLink, scope: CoroutineScope, config: RouterConfig): MavlinkRouter {
        require(other !== stationLink) { "a station cannot forward to its own link" }
        val router = MavlinkRouter.forStation(stationLink, other, scope, config, codec) { routers.remove(it) }
        routers += router
        return router
    }
}
