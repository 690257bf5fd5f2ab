package pod.e2e

import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import kotlinx.serialization.json.addJsonObject
import kotlinx.serialization.json.buildJsonArray
import kotlinx.serialization.json.put
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import java.net.DatagramSocket
import java.net.InetAddress
import kotlin.time.Duration.Companion.seconds

/** The system id mavsdk_vehicle.py is started with. */
internal const val MAVSDK_VEHICLE_SYSID = 17

/**
 * Runs [block] with a Pod ground station listening on loopback and MAVSDK 4 as the vehicle
 * (mavsdk_vehicle.py with [flags]: an AUTOPILOT component sending to our port; with a
 * MissionRawServer unless told otherwise, and ParamServer / ActionServer when asked), the station
 * configured by [station].
 */
internal suspend fun withMavsdkVehicle(
    vararg flags: String,
    station: GroundStationConfig = GroundStationConfig(),
    block: suspend (MavlinkVehicle, JsonPeer) -> Unit,
) = coroutineScope {
    val gcs = GroundStation.open("udpin://127.0.0.1:0", this, station)
    val peer = Python.startJson("mavsdk_vehicle.py", gcs.link.localPort, MAVSDK_VEHICLE_SYSID, 40, *flags)
    try {
        withTimeout(15.seconds) { peer.await("ready") }
        val vehicle = withTimeout(10.seconds) { gcs.vehicles.first { MAVSDK_VEHICLE_SYSID in it } }.getValue(MAVSDK_VEHICLE_SYSID)
        withTimeout(30.seconds) { block(vehicle, peer) }
    } finally {
        peer.stop()
        gcs.close()
    }
}

/** A UDP port on loopback that was free a moment ago (MAVSDK cannot report the port it bound). */
internal fun freeUdpPort(): Int = DatagramSocket(0, InetAddress.getLoopbackAddress()).use { it.localPort }

/**
 * A mission of [count] items (count ≥ 3) that uses what MISSION_ITEM_INT carries: a takeoff with
 * NaN yaw, waypoints in absolute and relative frames with hold times, acceptance radii, yaw (NaN
 * or not) and altitudes that are not round in binary, speed changes and jumps in MAV_FRAME_MISSION,
 * a timed loiter in an _INT frame that does not continue on its own, and a final RTL.
 */
internal fun variedMission(count: Int): List<MissionItem> {
    require(count >= 3) { "count must be ≥ 3, was $count" }
    val lat = 411_780_460
    val lon = -85_957_860
    return List(count) { i ->
        when {
            i == 0 -> MissionItem(seq = 0, frame = 3, command = 22, current = true, param1 = 15f, param4 = Float.NaN, x = lat, y = lon, z = 30f)
            i == count - 1 -> MissionItem(seq = i, frame = 2, command = 20)
            i % 10 == 5 -> MissionItem(seq = i, frame = 2, command = 178, param1 = 1f, param2 = 12.5f, param3 = -1f)
            i % 10 == 7 -> MissionItem(
                seq = i, frame = 6, command = 19, autocontinue = false, param1 = 20f, param3 = -35.5f,
                x = lat + 1234 * i, y = lon - 987 * i, z = 42.125f,
            )
            i % 10 == 9 -> MissionItem(seq = i, frame = 2, command = 177, param1 = (i - 3).toFloat(), param2 = 1f)
            else -> MissionItem(
                seq = i, frame = if (i % 2 == 0) 3 else 0, command = 16,
                param1 = (i % 3).toFloat(), param2 = 2.5f, param4 = if (i % 4 == 0) Float.NaN else i * 7.5f,
                x = lat + 1234 * i, y = lon - 987 * i, z = if (i % 2 == 0) 30f + i * 0.1f else 150.3f + i,
            )
        }
    }
}

/** [count] polygon vertices of an inclusion fence around Porto (param1 = vertex count). */
internal fun fence(count: Int): List<MissionItem> = List(count) { i ->
    MissionItem(seq = i, frame = 5, command = 5001, param1 = count.toFloat(), x = 411_700_000 + 5000 * (i % 2), y = -85_900_000 + 5000 * (i / 2), missionType = MissionType.FENCE)
}

/** [count] rally points at 50 m above home. */
internal fun rally(count: Int): List<MissionItem> = List(count) { i ->
    MissionItem(seq = i, frame = 6, command = 5100, x = 411_750_000 + 3000 * i, y = -85_950_000, z = 50f, missionType = MissionType.RALLY)
}

/** An item as the MAVSDK scripts print it (fields named as in MISSION_ITEM_INT). */
internal fun Map<String, String>.toMissionItem(): MissionItem {
    fun int(name: String) = getValue(name).toInt()
    fun float(name: String) = getValue(name).toDouble().toFloat()
    return MissionItem(
        seq = int("seq"), frame = int("frame"), command = int("command"),
        current = int("current") != 0, autocontinue = int("autocontinue") != 0,
        param1 = float("param1"), param2 = float("param2"), param3 = float("param3"), param4 = float("param4"),
        x = int("x"), y = int("y"), z = float("z"),
        missionType = MissionType.of(int("mission_type")) ?: error("unknown mission_type in $this"),
    )
}

/**
 * The items as a JSON array for the MAVSDK scripts. Floats are written as the exact double value
 * of the float (NaN as NaN, which Python's json reads), so Python's float → float32 is exact.
 */
internal fun List<MissionItem>.toJson(): String = buildJsonArray {
    for (it in this@toJson) {
        addJsonObject {
            put("seq", it.seq)
            put("frame", it.frame)
            put("command", it.command)
            put("current", if (it.current) 1 else 0)
            put("autocontinue", if (it.autocontinue) 1 else 0)
            put("param1", it.param1.toDouble())
            put("param2", it.param2.toDouble())
            put("param3", it.param3.toDouble())
            put("param4", it.param4.toDouble())
            put("x", it.x)
            put("y", it.y)
            put("z", it.z.toDouble())
            put("mission_type", it.missionType.mavValue)
        }
    }
}.toString()
