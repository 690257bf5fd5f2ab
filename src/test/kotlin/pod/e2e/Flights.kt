package pod.e2e

import java.util.concurrent.CopyOnWriteArrayList
import kotlin.math.roundToLong
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.MavCommands.DO_LAND_START
import pod.mavlink.command.MavCommands.NAV_LAND
import pod.mavlink.command.MavCommands.NAV_LOITER_TURNS
import pod.mavlink.command.MavCommands.NAV_RETURN_TO_LAUNCH
import pod.mavlink.command.MavCommands.NAV_TAKEOFF
import pod.mavlink.command.MavCommands.NAV_WAYPOINT
import pod.mavlink.mission.MissionItem
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig

/** Missions and helpers for flight tests against simulated vehicles. */
internal object Flights {
    /** Altitudes above home. */
    private const val FRAME_RELATIVE = 3

    fun item(seq: Int, command: Int, at: Location? = null, altitude: Double = 0.0, p1: Float = 0f, p2: Float = 0f, p3: Float = 0f) = MissionItem(
        seq = seq, frame = FRAME_RELATIVE, command = command, param1 = p1, param2 = p2, param3 = p3,
        x = at?.let { (it.latitude * 1e7).roundToLong().toInt() } ?: 0,
        y = at?.let { (it.longitude * 1e7).roundToLong().toInt() } ?: 0,
        z = altitude.toFloat(),
    )

    /** Item 0 as ArduPilot keeps it: home, absolute altitude. */
    fun home(at: Location) = item(0, NAV_WAYPOINT, at).copy(frame = 0, z = at.altitude.meters.toFloat())

    /** Takeoff to 20 m, [side] north, [side] east, return to launch: a copter's L out and home. */
    fun copterLeg(home: Location, side: Double): List<MissionItem> = listOf(
        home(home),
        item(1, NAV_TAKEOFF, altitude = 20.0),
        item(2, NAV_WAYPOINT, home.offset(side.m, 0.m), 20.0),
        item(3, NAV_WAYPOINT, home.offset(side.m, side.m), 20.0),
        item(4, NAV_RETURN_TO_LAUNCH),
    )

    /** Takeoff to 20 m, five waypoints around home, two loiter turns at the last one, return to launch. */
    fun copterSurvey(home: Location): List<MissionItem> {
        val points = listOf(40 to 0, 40 to 40, 0 to 60, -40 to 40, -30 to 0).map { (n, e) -> home.offset(n.m, e.m) }
        return listOf(home(home), item(1, NAV_TAKEOFF, altitude = 20.0)) +
            points.mapIndexed { i, p -> item(2 + i, NAV_WAYPOINT, p, 20.0 + 5 * i) } +
            item(7, NAV_LOITER_TURNS, points.last(), 30.0, p1 = 2f, p3 = 15f) +
            item(8, NAV_RETURN_TO_LAUNCH)
    }

    /** A plane's circuit: takeoff to 40 m, three waypoints, then a landing sequence back onto home from the north. */
    fun planeCircuit(home: Location): List<MissionItem> = listOf(
        home(home),
        item(1, NAV_TAKEOFF, altitude = 40.0, p1 = 15f),
        item(2, NAV_WAYPOINT, home.offset(0.m, 500.m), 60.0),
        item(3, NAV_WAYPOINT, home.offset(600.m, 500.m), 60.0),
        item(4, NAV_WAYPOINT, home.offset(900.m, 0.m), 50.0),
        item(5, DO_LAND_START),
        item(6, NAV_WAYPOINT, home.offset(500.m, 0.m), 30.0),
        item(7, NAV_LAND, home, 0.0),
    )

    /**
     * Runs [block] with one simulated vehicle ([config], sending to a fresh ground station on
     * loopback) once the station sees it ready to arm ([vehicle]); stops both afterwards.
     */
    suspend fun flying(
        config: SimVehicleConfig,
        station: GroundStationConfig = GroundStationConfig(),
        block: suspend CoroutineScope.(MavlinkVehicle, SimVehicle) -> Unit,
    ) = coroutineScope {
        val gcs = GroundStation.open("udpin://127.0.0.1:0", this, station)
        val sim = SimVehicle(config.copy(gcs = "udpout://127.0.0.1:${gcs.link.localPort}"))
        try {
            sim.start(this)
            block(vehicle(gcs, config.systemId), sim)
        } finally {
            sim.stop()
            gcs.close()
        }
    }

    /** The vehicle [systemId] once [gcs] has heard it, has its position and a 3D GPS fix (it can arm). */
    suspend fun vehicle(gcs: GroundStation, systemId: Int): MavlinkVehicle {
        val vehicle = withTimeout(15.seconds) { gcs.vehicles.first { systemId in it } }.getValue(systemId)
        withTimeout(15.seconds) { vehicle.telemetry.position.first { it != null } }
        withTimeout(15.seconds) { vehicle.telemetry.gps.first { it?.has3dFix == true } }
        return vehicle
    }

    /**
     * Turns off the autopilot's disarm of a vehicle armed on the ground that has not taken off
     * (DISARM_DELAY 0 on ArduCopter, COM_DISARM_PRFLT -1 on PX4). With an accelerated time scale
     * its 10 s pass before the 1 Hz heartbeat has even confirmed the arming.
     */
    suspend fun keepArmedOnGround(vehicle: MavlinkVehicle) {
        if (vehicle.identity.value.autopilot == pod.core.vehicle.Autopilot.PX4) {
            vehicle.params.write("COM_DISARM_PRFLT", -1.0)
        } else if (vehicle.identity.value.type != pod.core.vehicle.VehicleType.FIXED_WING) {
            vehicle.params.write("DISARM_DELAY", 0.0)
        }
    }

    /** Starts recording the items [vehicle] reports reached; cancel the returned job when done. */
    fun CoroutineScope.recordReached(vehicle: MavlinkVehicle): Pair<List<Int>, Job> {
        val reached = CopyOnWriteArrayList<Int>()
        val job = launch(start = kotlinx.coroutines.CoroutineStart.UNDISPATCHED) { vehicle.telemetry.itemReached.collect { reached += it } }
        return reached to job
    }
}
