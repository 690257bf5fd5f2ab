package pod.mavlink.command

import pod.mavlink.MavFrames
import pod.mavlink.codec.EncodedPayload
import pod.mavlink.codec.writeLe

import io.dronefleet.mavlink.common.CommandAck
import io.dronefleet.mavlink.common.CommandInt
import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.MavCmd
import io.dronefleet.mavlink.common.MavFrame
import io.dronefleet.mavlink.common.MavResult
import io.dronefleet.mavlink.util.EnumValue
import kotlin.math.roundToLong

/** Translates [VehicleCommand]s to COMMAND_LONG / COMMAND_INT and COMMAND_ACK to [CommandReply]. */
public object CommandWire {

    /** The COMMAND_LONG or COMMAND_INT for [command], addressed to ([targetSystem], [targetComponent]). */
    public fun encode(command: VehicleCommand, targetSystem: Int, targetComponent: Int, confirmation: Int = 0): Any {
        val frame = command.frame ?: return CommandLong.builder()
            .targetSystem(targetSystem).targetComponent(targetComponent)
            .command(EnumValue.create<MavCmd>(command.command)).confirmation(confirmation)
            .param1(command.param1).param2(command.param2).param3(command.param3).param4(command.param4)
            .param5(command.param5.toFloat()).param6(command.param6.toFloat()).param7(command.param7)
            .build()
        val scale = if (MavFrames.isGlobal(frame)) 1e7 else 1.0
        return CommandInt.builder()
            .targetSystem(targetSystem).targetComponent(targetComponent)
            .frame(EnumValue.create<MavFrame>(frame)).command(EnumValue.create<MavCmd>(command.command))
            .param1(command.param1).param2(command.param2).param3(command.param3).param4(command.param4)
            .x((command.param5 * scale).roundToLong().toInt()).y((command.param6 * scale).roundToLong().toInt())
            .z(command.param7)
            .build()
    }

    /**
     * [encode]'s COMMAND_LONG for a [command] without a frame, written field by field: the same
     * bytes, without the io.dronefleet builder and the generic plan (see [EncodedPayload]). The
     * layout is common.xml's COMMAND_LONG (id 76, CRC_EXTRA 152): param1 to param7 as floats,
     * command as uint16, then target system, target component and confirmation as uint8.
     */
    internal fun encodeLong(command: VehicleCommand, targetSystem: Int, targetComponent: Int, confirmation: Int = 0): EncodedPayload {
        require(command.frame == null) { "a command with a frame travels as COMMAND_INT" }
        val payload = ByteArray(COMMAND_LONG_LENGTH)
        val params = floatArrayOf(
            command.param1, command.param2, command.param3, command.param4,
            command.param5.toFloat(), command.param6.toFloat(), command.param7,
        )
        for (i in params.indices) payload.writeLe(i * 4, 4, params[i].toRawBits().toLong())
        payload.writeLe(28, 2, command.command.toLong())
        payload[30] = targetSystem.toByte()
        payload[31] = targetComponent.toByte()
        payload[32] = confirmation.toByte()
        return EncodedPayload(COMMAND_LONG_ID, payload)
    }

    private const val COMMAND_LONG_ID = 76
    private const val COMMAND_LONG_LENGTH = 33

    /** The command an incoming COMMAND_LONG or COMMAND_INT carries (the inverse of [encode]), or null. */
    public fun decode(message: Any): VehicleCommand? = when (message) {
        is CommandLong -> VehicleCommand(
            message.command().value(), message.param1(), message.param2(), message.param3(), message.param4(),
            message.param5().toDouble(), message.param6().toDouble(), message.param7(),
        )
        is CommandInt -> {
            val frame = message.frame().value()
            val scale = if (MavFrames.isGlobal(frame)) 1e-7 else 1.0
            VehicleCommand(
                message.command().value(), message.param1(), message.param2(), message.param3(), message.param4(),
                message.x() * scale, message.y() * scale, message.z(), frame,
            )
        }
        else -> null
    }

    /** The reply a COMMAND_ACK carries, or null for any other message. */
    public fun reply(message: Any): CommandReply? = (message as? CommandAck)?.let { ack ->
        CommandReply(
            command = ack.command().value(),
            resultCode = ack.result().value(),
            progress = ack.progress().takeIf { it in 0..100 },
            resultParam2 = ack.resultParam2(),
        )
    }

    /** A COMMAND_ACK answering [command] with [result] to ([targetSystem], [targetComponent]). */
    public fun ack(command: Int, result: CommandResult, targetSystem: Int, targetComponent: Int, progress: Int? = null): CommandAck =
        CommandAck.builder()
            .command(EnumValue.create<MavCmd>(command))
            .result(EnumValue.create<MavResult>(result.mavValue))
            .progress(progress ?: if (result == CommandResult.IN_PROGRESS) 255 else 0)
            .targetSystem(targetSystem)
            .targetComponent(targetComponent)
            .build()
}
