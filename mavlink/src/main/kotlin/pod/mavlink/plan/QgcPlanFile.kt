package pod.mavlink.plan

import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.JsonUnquotedLiteral
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.WplFile
import java.math.BigDecimal
import java.nio.file.Files
import java.nio.file.Path

/**
 * Reads and writes QGroundControl .plan files (JSON): mission simple items, survey complex items (read as their
 * expanded items), geofence polygons and circles, rally points and planned home.
 *
 * The layout follows QGC's writers and readers (mavlink/qgroundcontrol): `PlanMasterController::saveToJson`
 * (fileType "Plan", version 1, groundStation, mission, geoFence, rallyPoints), `MissionController::_saveJson` /
 * `_loadJsonMissionFileV2` (mission version 2: firmwareType, vehicleType, cruiseSpeed, hoverSpeed, items,
 * plannedHomePosition [lat, lon, alt]), `SimpleMissionItem::save` / `MissionItem::save` (type "SimpleItem",
 * command, frame, autoContinue, doJumpId, params[7] with NaN written as null), `TransectStyleComplexItem::_save`
 * ("Items": the expanded simple items), `GeoFenceController::save` (geoFence version 2, polygons of
 * `QGCFencePolygon` {inclusion, polygon [[lat, lon]…], version 1}, circles of `QGCFenceCircle`
 * {circle {center, radius}, inclusion, version 1}) and `RallyPointController::save` (rallyPoints version 2,
 * points [[lat, lon, alt]…]); docs: qgc-dev-guide/file_formats/plan.md.
 *
 * Item params 5 and 6 are mapped as [WplFile] maps WPL's x/y columns: degrees × 10⁷ in global frames, metres ×
 * 10⁴ in local frames, plain integers otherwise; a `null` there (QGC's NaN) reads as 0 since MISSION_ITEM_INT
 * carries an integer. Keys are written sorted, four-space indented, as QGC's QJsonDocument writes them.
 */
public object QgcPlanFile {
    /** The `version` of the file this object writes. */
    public const val FILE_VERSION: Int = 1

    // Version numbers of the sections as QGC writes them today.
    private const val MISSION_VERSION = 2
    private const val FENCE_VERSION = 2
    private const val FENCE_SHAPE_VERSION = 1
    private const val RALLY_VERSION = 2

    @OptIn(ExperimentalSerializationApi::class)
    private val json = Json {
        prettyPrint = true
        prettyPrintIndent = "    "
    }

    /**
     * The plan in [text].
     *
     * @throws QgcPlanFormatException naming the JSON path of the first value that cannot be read and why.
     */
    public fun read(text: String): QgcPlan = QgcPlanReader.read(text)

    /** Reads the UTF-8 .plan file at [path]; see [read]. */
    public fun read(path: Path): QgcPlan = read(Files.readString(path))

    /**
     * The .plan JSON text of [plan].
     *
     * @throws IllegalArgumentException when an item's seq is not its index, a param is infinite (JSON has no
     *   infinity; NaN is written as null), or a coordinate, radius or speed is not a finite number.
     */
    public fun write(plan: QgcPlan): String = json.encodeToString(JsonElement.serializer(), toJson(plan)) + "\n"

    /** Writes [plan] to [path] as UTF-8 (see [write]), replacing the file. */
    public fun write(path: Path, plan: QgcPlan) {
        Files.writeString(path, write(plan))
    }

    internal fun toJson(plan: QgcPlan): JsonObject {
        val mission = buildMap {
            putAll(plan.missionExtras)
            plan.cruiseSpeed?.let { put("cruiseSpeed", finite(it, "cruiseSpeed")) }
            put("firmwareType", JsonPrimitive(plan.firmwareType))
            plan.hoverSpeed?.let { put("hoverSpeed", finite(it, "hoverSpeed")) }
            put("items", JsonArray(plan.mission.mapIndexed { index, item -> item(index, item, plan.itemExtras[index]) }))
            plan.plannedHome?.let { put("plannedHomePosition", position(it, "plannedHomePosition")) }
            put("vehicleType", JsonPrimitive(plan.vehicleType))
            put("version", JsonPrimitive(MISSION_VERSION))
        }
        val fence = mapOf(
            "circles" to JsonArray(
                plan.geoFence.circles.mapIndexed { index, circle ->
                    require(circle.radiusMetres.isFinite() && circle.radiusMetres > 0) {
                        "geoFence.circles[$index].radiusMetres must be > 0, was ${circle.radiusMetres}"
                    }
                    sorted(
                        "circle" to JsonObject(
                            mapOf(
                                "center" to point(circle.center, "geoFence.circles[$index].center"),
                                "radius" to JsonPrimitive(circle.radiusMetres),
                            ),
                        ),
                        "inclusion" to JsonPrimitive(circle.inclusion),
                        "version" to JsonPrimitive(FENCE_SHAPE_VERSION),
                    )
                },
            ),
            "polygons" to JsonArray(
                plan.geoFence.polygons.mapIndexed { index, polygon ->
                    sorted(
                        "inclusion" to JsonPrimitive(polygon.inclusion),
                        "polygon" to JsonArray(
                            polygon.vertices.mapIndexed { corner, vertex -> point(vertex, "geoFence.polygons[$index][$corner]") },
                        ),
                        "version" to JsonPrimitive(FENCE_SHAPE_VERSION),
                    )
                },
            ),
            "version" to JsonPrimitive(FENCE_VERSION),
        )
        val rally = mapOf(
            "points" to JsonArray(plan.rallyPoints.mapIndexed { index, point -> position(point, "rallyPoints[$index]") }),
            "version" to JsonPrimitive(RALLY_VERSION),
        )
        val root = buildMap {
            putAll(plan.extras)
            put("fileType", JsonPrimitive("Plan"))
            put("geoFence", JsonObject(fence))
            put("groundStation", JsonPrimitive(plan.groundStation))
            put("mission", JsonObject(mission.toSortedMap()))
            put("rallyPoints", JsonObject(rally))
            put("version", JsonPrimitive(FILE_VERSION))
        }
        return JsonObject(root.toSortedMap())
    }

    private fun item(index: Int, item: MissionItem, extras: JsonObject?): JsonObject {
        require(item.seq == index) { "mission[$index].seq must be $index, was ${item.seq}" }
        val params = listOf(item.param1, item.param2, item.param3, item.param4).mapIndexed { i, value ->
            param(value, "mission[$index].param${i + 1}")
        } + listOf(coordinate(item.frame, item.x), coordinate(item.frame, item.y), param(item.z, "mission[$index].z"))
        val fields = buildMap {
            extras?.let { putAll(it) }
            put("autoContinue", JsonPrimitive(item.autocontinue))
            put("command", JsonPrimitive(item.command))
            if ("doJumpId" !in this) put("doJumpId", JsonPrimitive(index + 1))
            put("frame", JsonPrimitive(item.frame))
            put("params", JsonArray(params))
            put("type", JsonPrimitive("SimpleItem"))
        }
        return JsonObject(fields.toSortedMap())
    }

    private fun param(value: Float, name: String): JsonElement {
        require(!value.isInfinite()) { "$name is $value: a .plan file (JSON) cannot hold infinity" }
        return if (value.isNaN()) JsonNull else literal(WplFile.formatFloat(value))
    }

    // Exact decimals, the same digits as WPL writes: going through Double could print 41.123456699999996.
    private fun coordinate(frame: Int, value: Int): JsonElement = when (frame) {
        in MissionItem.GLOBAL_FRAMES -> literal(BigDecimal.valueOf(value.toLong(), 7).toPlainString())
        in MissionItem.LOCAL_FRAMES -> literal(BigDecimal.valueOf(value.toLong(), 4).toPlainString())
        else -> JsonPrimitive(value)
    }

    @OptIn(ExperimentalSerializationApi::class)
    private fun literal(number: String): JsonElement = JsonUnquotedLiteral(number)

    private fun point(point: PlanPoint, name: String): JsonArray {
        require(point.latitude in -90.0..90.0) { "$name latitude ${point.latitude} is outside ±90°" }
        require(point.longitude in -180.0..180.0) { "$name longitude ${point.longitude} is outside ±180°" }
        return JsonArray(listOf(JsonPrimitive(point.latitude), JsonPrimitive(point.longitude)))
    }

    private fun position(position: PlanPosition, name: String): JsonArray {
        require(!position.altitude.isInfinite()) { "$name altitude is ${position.altitude}" }
        val altitude = if (position.altitude.isNaN()) JsonNull else JsonPrimitive(position.altitude)
        return JsonArray(point(PlanPoint(position.latitude, position.longitude), name) + altitude)
    }

    private fun finite(value: Double, name: String): JsonPrimitive {
        require(value.isFinite()) { "$name must be a finite number, was $value" }
        return JsonPrimitive(value)
    }

    private fun sorted(vararg fields: Pair<String, JsonElement>): JsonObject = JsonObject(sortedMapOf(*fields))
}
