package pod.bench.mission

import kotlinx.coroutines.CoroutineScope
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.addJsonObject
import kotlinx.serialization.json.buildJsonArray
import kotlinx.serialization.json.put
import pod.bench.RelayedVehicle
import pod.core.vehicle.Autopilot
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.sim.SimVehicleConfig

/** The simulated vehicle's system id in every run. */
const val VEHICLE_SYSTEM_ID = 21

/**
 * A fresh simulated vehicle of [cell]'s flavour behind a fresh relay that drops [Cell.loss] of the
 * datagrams each way, seeded with [seed], sending to a ground station on loopback port [gcsPort].
 */
suspend fun startCellVehicle(scope: CoroutineScope, cell: Cell, seed: Long, gcsPort: Int): RelayedVehicle =
    RelayedVehicle.start(scope, SimVehicleConfig(systemId = VEHICLE_SYSTEM_ID, autopilot = cell.flavour), cell.loss, seed, gcsPort)

/**
 * [count] NAV_WAYPOINTs (16) in MAV_FRAME_GLOBAL_RELATIVE_ALT_INT (6), in a line going north of
 * Porto, 10 m apart, 30 m above home; item 0 current. Every field is exact in float32, so a
 * download that went through MAVSDK's JSON compares equal.
 */
fun benchMission(count: Int): List<MissionItem> = List(count) { i ->
    MissionItem(
        seq = i,
        frame = 6,
        command = 16,
        current = i == 0,
        param2 = 2f, // acceptance radius
        x = 411_780_460 + 900 * i,
        y = -85_957_860 + 37 * (i % 50),
        z = 30f + (i % 8) * 0.5f,
    )
}

/**
 * Null when [back] holds what was [sent], else what differs. ArduPilot keeps home in item 0
 * whatever was sent there, so it is compared from item 1; `current` is not compared (a vehicle
 * reports its own current item).
 */
fun missionMismatch(autopilot: Autopilot, sent: List<MissionItem>, back: List<MissionItem>): String? {
    if (back.size != sent.size) return "came back with ${back.size} items, sent ${sent.size}"
    val skip = if (autopilot == Autopilot.ARDUPILOT) 1 else 0
    for (i in skip until sent.size) {
        val a = sent[i].copy(current = false)
        val b = back[i].copy(current = false)
        if (a != b) return "item $i differs: sent $a, came back $b"
    }
    return null
}

/**
 * The items as the JSON array bench/mavsdk_mission.py reads (MISSION_ITEM_INT field names). Floats
 * go as the exact double of the float (NaN as NaN, which Python's json reads), so Python's float →
 * float32 gives them back exactly.
 */
fun List<MissionItem>.toMavsdkJson(): String = missionItemsJson(this).toString() + "\n"

/** [items] as a JSON array of MISSION_ITEM_INT objects. */
fun missionItemsJson(items: List<MissionItem>): JsonArray = buildJsonArray {
    for (item in items) {
        addJsonObject {
            put("seq", item.seq)
            put("frame", item.frame)
            put("command", item.command)
            put("current", if (item.current) 1 else 0)
            put("autocontinue", if (item.autocontinue) 1 else 0)
            put("param1", item.param1.toDouble())
            put("param2", item.param2.toDouble())
            put("param3", item.param3.toDouble())
            put("param4", item.param4.toDouble())
            put("x", item.x)
            put("y", item.y)
            put("z", item.z.toDouble())
            put("mission_type", item.missionType.mavValue)
        }
    }
}

/** An "item" event of bench/mavsdk_mission.py as a [MissionItem]. */
fun Map<String, String>.toMissionItem(): MissionItem {
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
