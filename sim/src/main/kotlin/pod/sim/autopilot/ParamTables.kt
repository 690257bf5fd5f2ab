package pod.sim.autopilot

import pod.mavlink.param.ParamType.INT16
import pod.mavlink.param.ParamType.INT32
import pod.mavlink.param.ParamType.INT8
import pod.mavlink.param.ParamType.REAL32

/**
 * The parameters each simulated firmware carries (its profile picks the table): a realistic subset, with the real names, units
 * and defaults, that the simulated flight reads (so a PARAM_SET changes how it flies). Ranges are
 * the documented ones; the simulated PX4 refuses values outside them, the simulated ArduPilot
 * stores whatever it is sent, as the real one does.
 */
internal object ParamTables {

    /** ArduCopter's table, with [systemId] as MAV_SYSID. */
    fun arduCopter(systemId: Int): List<ParamDef> = arduCommon(systemId) + arduCopterOnly + arduFence(copter = true)

    /** ArduPlane's table, with [systemId] as MAV_SYSID. */
    fun arduPlane(systemId: Int): List<ParamDef> = arduCommon(systemId) + arduPlaneOnly + arduFence(copter = false)

    /** PX4's multicopter table, with [systemId] as MAV_SYS_ID. */
    fun px4Multicopter(systemId: Int): List<ParamDef> = px4Common(systemId) + px4MulticopterOnly

    /** PX4's fixed-wing table, with [systemId] as MAV_SYS_ID. */
    fun px4FixedWing(systemId: Int): List<ParamDef> = px4Common(systemId) + px4FixedWingOnly

    /**
     * The fence parameters the simulated fence reads, with AC_Fence.cpp's var_info defaults:
     * disabled; FENCE_TYPE 7 on Copter (max altitude, circle, polygons), 4 on Plane (polygons);
     * action 1 (Copter RTL or LAND, Plane RTL); FENCE_OPTIONS 1 on Plane (no mode change while
     * recovering from a breach), 0 on Copter.
     */
    private fun arduFence(copter: Boolean) = listOfNotNull(
        ParamDef("FENCE_ENABLE", 0.0, INT8, 0.0, 1.0),
        ParamDef("FENCE_TYPE", if (copter) 7.0 else 4.0, INT8, 0.0, 15.0),
        ParamDef("FENCE_ACTION", 1.0, INT8, 0.0, 8.0),
        ParamDef("FENCE_ALT_MAX", 100.0, REAL32, 10.0, 1000.0), // m above home
        ParamDef("FENCE_RADIUS", 300.0, REAL32, 30.0, 10000.0), // m around home
        ParamDef("FENCE_MARGIN", 2.0, REAL32, 1.0, 10.0), // m
        ParamDef("FENCE_OPTIONS", if (copter) 0.0 else 1.0, INT16, 0.0, 7.0),
        ParamDef("FENCE_ALT_MIN", -10.0, REAL32, -100.0, 100.0).takeIf { !copter }, // m, sets Plane's return altitude
        ParamDef("FENCE_RET_ALT", 0.0, INT16, 0.0, 32767.0).takeIf { !copter }, // m above home, 0: half way
    )

    // ArduPilot 4.7 calls the system id MAV_SYSID (SYSID_THISMAV before 4.7).
    private fun arduCommon(systemId: Int) = listOf(
        ParamDef("MAV_SYSID", systemId.toDouble(), INT16, 1.0, 255.0),
        ParamDef("ARMING_CHECK", 1.0, INT32, 0.0, Int.MAX_VALUE.toDouble()),
        ParamDef("BATT_CAPACITY", 3300.0, INT32, 0.0, 1e6),
        ParamDef("BATT_LOW_VOLT", 14.0, REAL32, 0.0, 100.0),
        // Real default 0 (check off); the simulator refuses to arm a 4S pack below ~21 % charge.
        ParamDef("BATT_ARM_VOLT", 14.6, REAL32, 0.0, 100.0),
        // An ordinary writable parameter on ArduPilot (AP_Stats.cpp declares it without a read-only flag).
        ParamDef("STAT_BOOTCNT", 1.0, INT16),
    )

    private val arduCopterOnly = listOf(
        ParamDef("WPNAV_SPEED", 500.0, REAL32, 10.0, 2000.0), // cm/s
        ParamDef("WPNAV_SPEED_UP", 250.0, REAL32, 10.0, 1000.0), // cm/s
        ParamDef("WPNAV_SPEED_DN", 150.0, REAL32, 10.0, 500.0), // cm/s
        ParamDef("WPNAV_RADIUS", 200.0, REAL32, 5.0, 1000.0), // cm
        ParamDef("WPNAV_ACCEL", 250.0, REAL32, 50.0, 500.0), // cm/s²
        ParamDef("RTL_ALT", 1500.0, INT32, 200.0, 300000.0), // cm
        ParamDef("RTL_SPEED", 0.0, REAL32, 0.0, 2000.0), // cm/s, 0 = WPNAV_SPEED
        ParamDef("LAND_SPEED", 50.0, INT16, 30.0, 200.0), // cm/s
        // Pilot climb and descent limits: the descent with the throttle stick at minimum (0 = PILOT_SPEED_UP).
        ParamDef("PILOT_SPEED_UP", 250.0, INT16, 50.0, 500.0), // cm/s
        ParamDef("PILOT_SPEED_DN", 0.0, INT16, 0.0, 500.0), // cm/s
        ParamDef("DISARM_DELAY", 10.0, INT8, 0.0, 127.0), // s
        ParamDef("CIRCLE_RADIUS", 500.0, REAL32, 0.0, 200000.0), // cm
        ParamDef("CIRCLE_RATE", 20.0, REAL32, -90.0, 90.0), // deg/s
        ParamDef("AUTO_OPTIONS", 0.0, INT32, 0.0, Int.MAX_VALUE.toDouble()), // bit 0: allow arming in AUTO
        ParamDef("FS_GCS_ENABLE", 0.0, INT8, 0.0, 7.0),
        // Read-only (@ReadOnly in ArduCopter/Parameters.cpp, k_software_type 10): a write is denied with a STATUSTEXT.
        ParamDef("SYSID_SW_TYPE", 10.0, INT8, readOnly = true),
    )

    private val arduPlaneOnly = listOf(
        ParamDef("AIRSPEED_CRUISE", 15.0, REAL32, 5.0, 100.0), // m/s
        ParamDef("AIRSPEED_MIN", 9.0, REAL32, 5.0, 100.0), // m/s
        ParamDef("AIRSPEED_MAX", 22.0, REAL32, 5.0, 100.0), // m/s
        ParamDef("WP_RADIUS", 90.0, INT16, 1.0, 32767.0), // m
        ParamDef("WP_LOITER_RAD", 60.0, INT16, -32767.0, 32767.0), // m, negative = counter-clockwise
        ParamDef("RTL_RADIUS", 0.0, INT16, -32767.0, 32767.0), // m, 0 = WP_LOITER_RAD
        ParamDef("ALT_HOLD_RTL", 10000.0, INT32, -1.0, 1e7), // cm, -1 = current altitude
        ParamDef("TKOFF_ALT", 50.0, INT16, 0.0, 32767.0), // m
        ParamDef("ROLL_LIMIT_DEG", 45.0, REAL32, 20.0, 90.0),
        ParamDef("TECS_CLMB_MAX", 5.0, REAL32, 0.1, 20.0), // m/s
        ParamDef("TECS_SINK_MAX", 5.0, REAL32, 0.0, 20.0), // m/s
        ParamDef("LAND_DISARMDELAY", 20.0, INT8, 0.0, 127.0), // s
        // 0 (the default, ArduPlane Parameters.cpp) refuses to arm a mission holding DO_LAND_START.
        ParamDef("RTL_AUTOLAND", 0.0, INT8, 0.0, 3.0),
        // Flare triggers of the slope landing (AP_Landing.cpp var_info defaults).
        ParamDef("LAND_FLARE_ALT", 3.0, REAL32, 0.0, 30.0), // m
        ParamDef("LAND_FLARE_SEC", 2.0, REAL32, 0.0, 10.0), // s
        ParamDef("TECS_LAND_SINK", 0.25, REAL32, 0.0, 2.0), // m/s sink demanded in the flare
        ParamDef("FS_GCS_ENABL", 0.0, INT8, 0.0, 2.0),
        // Read-only (@ReadOnly in ArduPlane/Parameters.cpp, k_software_type 0).
        ParamDef("SYSID_SW_TYPE", 0.0, INT8, readOnly = true),
    )

    private fun px4Common(systemId: Int) = listOf(
        ParamDef("MAV_SYS_ID", systemId.toDouble(), INT32, 1.0, 250.0),
        ParamDef("MIS_TAKEOFF_ALT", 2.5, REAL32, 0.0, 1000.0), // m above home
        ParamDef("RTL_RETURN_ALT", 60.0, REAL32, 0.0, 1000.0), // m above home
        ParamDef("NAV_ACC_RAD", 10.0, REAL32, 0.05, 200.0), // m
        ParamDef("NAV_LOITER_RAD", 80.0, REAL32, 25.0, 1000.0), // m
        ParamDef("COM_DISARM_LAND", 2.0, REAL32, -1.0, 20.0), // s
        ParamDef("COM_DISARM_PRFLT", 10.0, REAL32, -1.0, 20.0), // s
        ParamDef("BAT_LOW_THR", 0.15, REAL32, 0.12, 0.5),
        ParamDef("NAV_DLL_ACT", 0.0, INT32, 0.0, 6.0),
        ParamDef("SYS_AUTOSTART", 4001.0, INT32, 0.0, 9999999.0),
        // Geofence (navigator/geofence_params.yaml) and the failsafe delay (commander_params).
        ParamDef("GF_ACTION", 2.0, INT32, 0.0, 5.0), // 0 none, 1 warn, 2 hold, 3 return, 4 terminate, 5 land
        ParamDef("GF_MAX_HOR_DIST", 0.0, REAL32, 0.0, 10000.0), // m from home, 0 = off
        ParamDef("GF_MAX_VER_DIST", 0.0, REAL32, 0.0, 10000.0), // m above home, 0 = off
        ParamDef("COM_FAIL_ACT_T", 5.0, REAL32, 0.0, 25.0), // s of Hold before a Return or Land failsafe
    )

    private val px4MulticopterOnly = listOf(
        ParamDef("MPC_XY_CRUISE", 5.0, REAL32, 3.0, 20.0), // m/s
        ParamDef("MPC_Z_VEL_MAX_UP", 3.0, REAL32, 0.5, 8.0), // m/s
        ParamDef("MPC_Z_VEL_MAX_DN", 1.5, REAL32, 0.5, 4.0), // m/s
        ParamDef("MPC_LAND_SPEED", 0.7, REAL32, 0.6, 4.0), // m/s
        ParamDef("MPC_ACC_HOR", 3.0, REAL32, 2.0, 15.0), // m/s²
        ParamDef("MPC_XY_VEL_MAX", 12.0, REAL32, 0.0, 20.0), // m/s, also the orbit's speed limit
        ParamDef("MC_ORBIT_RAD_MAX", 1000.0, REAL32, 1.0, 10000.0), // m (flight_task_orbit_params.yaml)
    )

    private val px4FixedWingOnly = listOf(
        ParamDef("FW_AIRSPD_TRIM", 15.0, REAL32, 0.5, 40.0), // m/s
        ParamDef("FW_AIRSPD_MIN", 10.0, REAL32, 0.5, 40.0), // m/s
        ParamDef("FW_AIRSPD_MAX", 20.0, REAL32, 0.5, 40.0), // m/s
        ParamDef("FW_R_LIM", 50.0, REAL32, 35.0, 65.0), // deg
        ParamDef("FW_T_CLMB_MAX", 5.0, REAL32, 1.0, 15.0), // m/s
        ParamDef("FW_T_SINK_MAX", 5.0, REAL32, 2.0, 15.0), // m/s
    )
}
