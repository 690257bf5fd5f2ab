package pod.mavlink.route

import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.MavCmd
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.ktor.network.sockets.InetSocketAddress
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.launch
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import pod.mavlink.link.MemoryNetwork

private val encoder = FrameEncoder()

/**
 * A MAVLink node beside a router under test: a link of its own on the memory network, keeping
 * every datagram it receives (the router sends one frame per datagram).
 */
internal class Node(val name: String, val link: MavlinkLink, private val to: LinkPeer?, scope: CoroutineScope) {
    val received = ArrayList<ByteArray>()

    init {
        scope.launch { link.receive { _, bytes -> synchronized(received) { received += bytes } } }
    }

    /** Sends [bytes] to the router: to its own remote, or to the router link's port it was given. */
    fun send(bytes: ByteArray) {
        if (to != null) link.sendNow(bytes, to) else link.peers.forEach { link.sendNow(bytes, it) }
    }

    fun receivedHex(): List<String> = synchronized(received) { received.map { it.hex() } }

    override fun toString(): String = name

    companion object {
        /** A node that sends to the router's listening link on [port] (an ephemeral port of its own). */
        fun toListening(name: String, network: MemoryNetwork, port: Int, scope: CoroutineScope): Node =
            Node(name, network.open("udpout://127.0.0.1:$port"), null, scope)

        /** A node listening on [port], where the router's `udpout` link [routerLink] sends. */
        fun listening(name: String, network: MemoryNetwork, port: Int, routerLink: MavlinkLink, scope: CoroutineScope): Node =
            Node(name, network.open("udpin://127.0.0.1:$port"), LinkPeer(InetSocketAddress("127.0.0.1", routerLink.localPort)), scope)
    }
}

internal fun ByteArray.hex(): String = joinToString("") { "%02x".format(it) }

/** A HEARTBEAT (no target field) from ([sys], [comp]); [tag] in custom_mode makes it unique. */
internal fun heartbeat(sys: Int, comp: Int, tag: Long = 0): ByteArray = encoder.encode(
    Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
        .baseMode(EnumValue.create(0)).customMode(tag).systemStatus(MavState.MAV_STATE_STANDBY).mavlinkVersion(3).build(),
    sys, comp, 0,
)

/** A COMMAND_LONG from ([sys], [comp]) to ([targetSys], [targetComp]); [tag] in param1 makes it unique. */
internal fun command(sys: Int, comp: Int, targetSys: Int, targetComp: Int, tag: Int = 0): ByteArray = encoder.encode(
    CommandLong.builder().targetSystem(targetSys).targetComponent(targetComp).command(MavCmd.MAV_CMD_COMPONENT_ARM_DISARM)
        .param1(tag.toFloat()).build(),
    sys, comp, 0,
)
