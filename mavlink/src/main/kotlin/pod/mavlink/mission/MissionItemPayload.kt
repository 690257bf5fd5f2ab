package pod.mavlink.mission

import pod.mavlink.codec.DirectPayload
import pod.mavlink.codec.writeLe

/**
 * MISSION_ITEM_INT (#73) for [item], addressed to ([targetSystem], [targetComponent]), written
 * straight from the item: what an upload sends once per item, answering each request on the
 * receive thread. The generic path (an io.dronefleet builder, three EnumValues and a boxed value
 * per field through method handles) was a quarter of the station's time per item in the profile
 * of issue 30; this writes the same bytes (MissionItemPayloadTest compares them).
 *
 * Wire order (MAVLink's rule: base fields by size, largest first, then the extension): param1–4,
 * x, y (int32), z (float), seq, command (uint16), target_system, target_component, frame, current,
 * autocontinue (uint8), then the extension mission_type.
 */
internal class MissionItemPayload(
    private val item: MissionItem,
    private val targetSystem: Int,
    private val targetComponent: Int,
) : DirectPayload {
    override val messageId: Int get() = ID
    override val length: Int get() = LENGTH
    override val baseLength: Int get() = LENGTH - 1

    override fun writePayload(out: ByteArray) {
        out.writeLe(0, 4, item.param1.toRawBits().toLong())
        out.writeLe(4, 4, item.param2.toRawBits().toLong())
        out.writeLe(8, 4, item.param3.toRawBits().toLong())
        out.writeLe(12, 4, item.param4.toRawBits().toLong())
        out.writeLe(16, 4, item.x.toLong())
        out.writeLe(20, 4, item.y.toLong())
        out.writeLe(24, 4, item.z.toRawBits().toLong())
        out.writeLe(28, 2, item.seq.toLong())
        out.writeLe(30, 2, item.command.toLong())
        out[32] = targetSystem.toByte()
        out[33] = targetComponent.toByte()
        out[34] = item.frame.toByte()
        out[35] = (if (item.current) 1 else 0).toByte()
        out[36] = (if (item.autocontinue) 1 else 0).toByte()
        out[37] = item.missionType.mavValue.toByte()
    }

    private companion object {
        const val ID = 73
        const val LENGTH = 38
    }
}
