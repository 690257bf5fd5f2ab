package pod.mavlink.mission

import io.dronefleet.mavlink.common.MavCmd
import io.dronefleet.mavlink.common.MavFrame
import io.dronefleet.mavlink.common.MavMissionResult
import io.dronefleet.mavlink.common.MavMissionType
import io.dronefleet.mavlink.common.MissionAck
import io.dronefleet.mavlink.common.MissionClearAll
import io.dronefleet.mavlink.common.MissionCount
import io.dronefleet.mavlink.common.MissionCurrent
import io.dronefleet.mavlink.common.MissionItem as LegacyMissionItem
import io.dronefleet.mavlink.common.MissionItemInt
import io.dronefleet.mavlink.common.MissionRequest
import io.dronefleet.mavlink.common.MissionRequestInt
import io.dronefleet.mavlink.common.MissionRequestList
import io.dronefleet.mavlink.common.MissionSetCurrent
import io.dronefleet.mavlink.common.MissionWritePartialList
import io.dronefleet.mavlink.util.EnumValue
import pod.mavlink.command.MavCommands.DO_DIGICAM_CONTROL

/**
 * Translates [MissionMessage]s to io.dronefleet messages addressed to one system, and back: for
 * the ground side's [MissionService] and the vehicle side's [pod.mavlink.vehicle.MissionFrames].
 */
internal object MissionWire {

    /** The MAVLink message for [message], addressed to ([targetSystem], [targetComponent]). */
    @Suppress("DEPRECATION") // MISSION_REQUEST and MISSION_SET_CURRENT are deprecated but still spoken
    fun encode(message: MissionMessage, targetSystem: Int, targetComponent: Int): Any = when (message) {
        is MissionMessage.Count -> MissionCount.builder().targetSystem(targetSystem).targetComponent(targetComponent)
            .count(message.count).missionType(type(message.type)).build()
        is MissionMessage.RequestList -> MissionRequestList.builder().targetSystem(targetSystem).targetComponent(targetComponent)
            .missionType(type(message.type)).build()
        is MissionMessage.Request -> if (message.legacy) {
            MissionRequest.builder().targetSystem(targetSystem).targetComponent(targetComponent)
                .seq(message.seq).missionType(type(message.type)).build()
        } else {
            MissionRequestInt.builder().targetSystem(targetSystem).targetComponent(targetComponent)
                .seq(message.seq).missionType(type(message.type)).build()
        }
        is MissionMessage.Item -> if (message.legacy) legacyItem(message.item, targetSystem, targetComponent) else message.item.let { item ->
            MissionItemInt.builder().targetSystem(targetSystem).targetComponent(targetComponent)
                .seq(item.seq).frame(EnumValue.create<MavFrame>(item.frame)).command(EnumValue.create<MavCmd>(item.command))
                .current(if (item.current) 1 else 0).autocontinue(if (item.autocontinue) 1 else 0)
                .param1(item.param1).param2(item.param2).param3(item.param3).param4(item.param4)
                .x(item.x).y(item.y).z(item.z).missionType(type(item.missionType)).build()
        }
        is MissionMessage.Ack -> MissionAck.builder().targetSystem(targetSystem).targetComponent(targetComponent)
            .type(EnumValue.create<MavMissionResult>(message.result.mavValue)).missionType(type(message.type)).build()
        is MissionMessage.ClearAll -> MissionClearAll.builder().targetSystem(targetSystem).targetComponent(targetComponent)
            .missionType(type(message.type)).build()
        is MissionMessage.WritePartial -> MissionWritePartialList.builder().targetSystem(targetSystem).targetComponent(targetComponent)
            .startIndex(message.start).endIndex(message.end).missionType(type(message.type)).build()
        is MissionMessage.SetCurrent -> MissionSetCurrent.builder().targetSystem(targetSystem).targetComponent(targetComponent)
            .seq(message.seq).build()
        is MissionMessage.Current -> MissionCurrent.builder().seq(message.seq).total(message.total).build()
    }

    /**
     * What the ground side hands the link for [message]: MISSION_ITEM_INT written straight from the
     * item ([MissionItemPayload], one per item of an upload), anything else as [encode] builds it.
     */
    fun encodeToSend(message: MissionMessage, targetSystem: Int, targetComponent: Int): Any =
        if (message is MissionMessage.Item && !message.legacy) {
            MissionItemPayload(message.item, targetSystem, targetComponent)
        } else {
            encode(message, targetSystem, targetComponent)
        }

    /**
     * The target_system of a mission-protocol message, read without reflection (it is asked of every
     * message heard during a transfer); null for other messages and for MISSION_CURRENT, which has none.
     */
    @Suppress("DEPRECATION")
    fun targetSystem(message: Any): Int? = when (message) {
        is MissionRequestInt -> message.targetSystem()
        is MissionRequest -> message.targetSystem()
        is MissionItemInt -> message.targetSystem()
        is LegacyMissionItem -> message.targetSystem()
        is MissionAck -> message.targetSystem()
        is MissionCount -> message.targetSystem()
        is MissionRequestList -> message.targetSystem()
        is MissionClearAll -> message.targetSystem()
        is MissionWritePartialList -> message.targetSystem()
        is MissionSetCurrent -> message.targetSystem()
        else -> null
    }

    /**
     * The [MissionMessage] that [message] carries, or null when it is not a mission-protocol
     * message or names a mission type or result this dialect does not define.
     */
    @Suppress("DEPRECATION")
    fun decode(message: Any): MissionMessage? = when (message) {
        is MissionCount -> type(message.missionType())?.let { MissionMessage.Count(it, message.count()) }
        is MissionRequestList -> type(message.missionType())?.let { MissionMessage.RequestList(it) }
        is MissionRequestInt -> type(message.missionType())?.let { MissionMessage.Request(it, message.seq()) }
        is MissionRequest -> type(message.missionType())?.let { MissionMessage.Request(it, message.seq(), legacy = true) }
        is MissionItemInt -> type(message.missionType())?.let { t ->
            MissionMessage.Item(
                MissionItem(
                    seq = message.seq(), frame = message.frame().value(), command = message.command().value(),
                    current = message.current() != 0, autocontinue = message.autocontinue() != 0,
                    param1 = message.param1(), param2 = message.param2(), param3 = message.param3(), param4 = message.param4(),
                    x = message.x(), y = message.y(), z = message.z(), missionType = t,
                ),
            )
        }
        is LegacyMissionItem -> type(message.missionType())?.let { t ->
            MissionMessage.Item(
                MissionItem(
                    seq = message.seq(), frame = message.frame().value(), command = message.command().value(),
                    current = message.current() != 0, autocontinue = message.autocontinue() != 0,
                    param1 = message.param1(), param2 = message.param2(), param3 = message.param3(), param4 = message.param4(),
                    x = toWire(message.x(), message.frame().value(), message.command().value()),
                    y = toWire(message.y(), message.frame().value(), message.command().value()),
                    z = message.z(), missionType = t,
                ),
                legacy = true,
            )
        }
        is MissionAck -> {
            val t = type(message.missionType())
            val r = MissionResult.of(message.type().value())
            if (t == null || r == null) null else MissionMessage.Ack(t, r)
        }
        is MissionClearAll -> type(message.missionType())?.let { MissionMessage.ClearAll(it) }
        is MissionWritePartialList -> type(message.missionType())?.let {
            MissionMessage.WritePartial(it, message.startIndex(), message.endIndex())
        }
        is MissionSetCurrent -> MissionMessage.SetCurrent(message.seq())
        is MissionCurrent -> MissionMessage.Current(message.seq(), message.total())
        else -> null
    }

    private fun legacyItem(item: MissionItem, targetSystem: Int, targetComponent: Int): LegacyMissionItem =
        LegacyMissionItem.builder().targetSystem(targetSystem).targetComponent(targetComponent)
            .seq(item.seq).frame(EnumValue.create<MavFrame>(item.frame)).command(EnumValue.create<MavCmd>(item.command))
            .current(if (item.current) 1 else 0).autocontinue(if (item.autocontinue) 1 else 0)
            .param1(item.param1).param2(item.param2).param3(item.param3).param4(item.param4)
            .x(fromWire(item.x, item.frame, item.command)).y(fromWire(item.y, item.frame, item.command)).z(item.z)
            .missionType(type(item.missionType)).build()

    /**
     * MISSION_ITEM carries x and y as floats: degrees in global frames, metres in local frames. As
     * ArduPilot does (AP_Mission::convert_MISSION_ITEM_to_MISSION_ITEM_INT), every command but the
     * two camera ones whose x and y are plain integers takes them as degrees × 10⁷; local frames
     * take metres × 10⁴ (MAVLink's MISSION_ITEM_INT definition).
     */
    private fun scale(frame: Int, command: Int): Float = when {
        command == DO_DIGICAM_CONFIGURE || command == DO_DIGICAM_CONTROL -> 1f
        frame in MissionItem.LOCAL_FRAMES -> 1e4f
        else -> 1e7f
    }

    private fun toWire(value: Float, frame: Int, command: Int): Int = (value * scale(frame, command)).toInt()

    private fun fromWire(value: Int, frame: Int, command: Int): Float = value / scale(frame, command)

    /** MAV_CMD_DO_DIGICAM_CONFIGURE, which MavCommands does not name. */
    private const val DO_DIGICAM_CONFIGURE = 202

    private fun type(type: MissionType): EnumValue<MavMissionType> = EnumValue.create(type.mavValue)

    private fun type(value: EnumValue<MavMissionType>?): MissionType? = MissionType.of(value?.value() ?: 0)
}
