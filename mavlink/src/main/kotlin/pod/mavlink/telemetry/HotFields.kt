package pod.mavlink.telemetry

import pod.mavlink.MessageIds
import pod.mavlink.codec.FrameView

// The five messages a vehicle streams most, read field by field straight from a frame's payload
// into reused primitive holders: no io.dronefleet object, no boxing. Offsets are the wire order of
// common.xml / minimal.xml (fields sorted by type size, largest first; extensions after, in
// declaration order), as mavgen lays them out. Every field is read, not only those telemetry uses,
// so that a property test can hold each reader to io.dronefleet's decoder field by field.

/** The message ids read in place (HEARTBEAT, SYS_STATUS, ATTITUDE, GLOBAL_POSITION_INT, VFR_HUD). */
internal object HotMessages {
    /** True for the ids [HotFields] reads. */
    fun isHot(messageId: Int): Boolean = when (messageId) {
        MessageIds.HEARTBEAT, MessageIds.SYS_STATUS, MessageIds.ATTITUDE, MessageIds.GLOBAL_POSITION_INT, MessageIds.VFR_HUD -> true
        else -> false
    }
}

/** HEARTBEAT (0). */
internal class HeartbeatFields {
    var customMode = 0L
    var type = 0
    var autopilot = 0
    var baseMode = 0
    var systemStatus = 0
    var mavlinkVersion = 0

    fun read(p: FrameView) {
        customMode = p.u32(0)
        type = p.u8(4)
        autopilot = p.u8(5)
        baseMode = p.u8(6)
        systemStatus = p.u8(7)
        mavlinkVersion = p.u8(8)
    }
}

/** SYS_STATUS (1), with its MAVLink 2 extensions (the extended sensor bitmaps). */
internal class SysStatusFields {
    var sensorsPresent = 0L
    var sensorsEnabled = 0L
    var sensorsHealth = 0L
    var load = 0
    var voltageBattery = 0
    var currentBattery = 0
    var dropRateComm = 0
    var errorsComm = 0
    var errorsCount1 = 0
    var errorsCount2 = 0
    var errorsCount3 = 0
    var errorsCount4 = 0
    var batteryRemaining = 0
    var sensorsPresentExtended = 0L
    var sensorsEnabledExtended = 0L
    var sensorsHealthExtended = 0L

    fun read(p: FrameView) {
        sensorsPresent = p.u32(0)
        sensorsEnabled = p.u32(4)
        sensorsHealth = p.u32(8)
        load = p.u16(12)
        voltageBattery = p.u16(14)
        currentBattery = p.i16(16)
        dropRateComm = p.u16(18)
        errorsComm = p.u16(20)
        errorsCount1 = p.u16(22)
        errorsCount2 = p.u16(24)
        errorsCount3 = p.u16(26)
        errorsCount4 = p.u16(28)
        batteryRemaining = p.i8(30)
        sensorsPresentExtended = p.u32(31)
        sensorsEnabledExtended = p.u32(35)
        sensorsHealthExtended = p.u32(39)
    }
}

/** ATTITUDE (30). */
internal class AttitudeFields {
    var timeBootMs = 0L
    var roll = 0f
    var pitch = 0f
    var yaw = 0f
    var rollSpeed = 0f
    var pitchSpeed = 0f
    var yawSpeed = 0f

    fun read(p: FrameView) {
        timeBootMs = p.u32(0)
        roll = p.f32(4)
        pitch = p.f32(8)
        yaw = p.f32(12)
        rollSpeed = p.f32(16)
        pitchSpeed = p.f32(20)
        yawSpeed = p.f32(24)
    }
}

/** GLOBAL_POSITION_INT (33). */
internal class GlobalPositionFields {
    var timeBootMs = 0L
    var lat = 0
    var lon = 0
    var alt = 0
    var relativeAlt = 0
    var vx = 0
    var vy = 0
    var vz = 0
    var hdg = 0

    fun read(p: FrameView) {
        timeBootMs = p.u32(0)
        lat = p.i32(4)
        lon = p.i32(8)
        alt = p.i32(12)
        relativeAlt = p.i32(16)
        vx = p.i16(20)
        vy = p.i16(22)
        vz = p.i16(24)
        hdg = p.u16(26)
    }
}

/** VFR_HUD (74). */
internal class VfrHudFields {
    var airspeed = 0f
    var groundspeed = 0f
    var alt = 0f
    var climb = 0f
    var heading = 0
    var throttle = 0

    fun read(p: FrameView) {
        airspeed = p.f32(0)
        groundspeed = p.f32(4)
        alt = p.f32(8)
        climb = p.f32(12)
        heading = p.i16(16)
        throttle = p.u16(18)
    }
}

/** One holder per hot message, owned by one receive path (a station) and refilled for every frame. */
internal class HotFields {
    val heartbeat = HeartbeatFields()
    val sysStatus = SysStatusFields()
    val attitude = AttitudeFields()
    val position = GlobalPositionFields()
    val hud = VfrHudFields()
}
