package pod.mavlink.vehicle

import pod.mavlink.mission.MissionMessage
import pod.mavlink.mission.MissionWire

/**
 * Mission-protocol messages as a vehicle reads and answers them: what of a ground station's
 * messages a [MissionServer] should see, and its replies as MAVLink messages addressed to the
 * [Asker].
 */
public object MissionFrames {
    /**
     * The mission message [message] (a decoded io.dronefleet message) carries, when it is one and
     * is addressed to [systemId] or to every system (target 0, or no target field); else null.
     */
    public fun read(message: Any, systemId: Int): MissionMessage? {
        val mission = MissionWire.decode(message) ?: return null
        val target = MissionWire.targetSystem(message)
        return if (target == null || target == 0 || target == systemId) mission else null
    }

    /** [reply] as the io.dronefleet message to send, addressed to [to]. */
    public fun write(reply: MissionMessage, to: Asker): Any = MissionWire.encode(reply, to.systemId, to.componentId)
}
