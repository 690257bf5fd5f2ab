package pod.mavlink.plan

import kotlinx.serialization.SerializationException
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.MissionValidation
import java.math.BigDecimal
import java.math.RoundingMode

/** The reading half of [QgcPlanFile]: walks the JSON tree, every failure naming the path it was at. */
internal object QgcPlanReader {
    private val rootKeys = setOf("fileType", "version", "groundStation", "mission", "geoFence", "rallyPoints")
    private val missionKeys = setOf("version", "firmwareType", "vehicleType", "cruiseSpeed", "hoverSpeed", "items", "plannedHomePosition")
    private val itemKeys = setOf("type", "command", "frame", "autoContinue", "params")
    private const val ALT_MODE_CALC_ABOVE_TERRAIN = 3

    fun read(text: String): QgcPlan {
        val root = try {
            Json.parseToJsonElement(text.removePrefix("\uFEFF"))
        } catch (e: SerializationException) {
            throw QgcPlanFormatException("", "not JSON: ${e.message?.lineSequence()?.firstOrNull()}")
        }
        val top = Node("", root).obj()
        val fileType = top.field("fileType").string()
        if (fileType != "Plan") top.fail("fileType is '$fileType', a .plan file says 'Plan'")
        top.field("version").int(1, 1)
        val warnings = mutableListOf<String>()
        val mission = top.field("mission").obj()
        mission.field("version").int(2, 2)
        val items = mutableListOf<MissionItem>()
        val itemExtras = mutableMapOf<Int, JsonObject>()
        mission.field("items").array().forEach { entry ->
            val fields = entry.obj()
            when (val type = fields.field("type").string()) {
                "SimpleItem" -> simple(fields, items, itemExtras, warnings)
                "ComplexItem" -> {
                    val kind = fields.optional("complexItemType")?.string() ?: "?"
                    val expanded = fields.optional("TransectStyleComplexItem")?.obj()?.optional("Items")?.array()
                        ?: entry.fail("complex item '$kind' has no TransectStyleComplexItem.Items: Pod cannot expand it")
                    val first = items.size
                    expanded.forEach { simple(it.obj(), items, itemExtras, warnings) }
                    warnings += "${entry.path}: $kind complex item read as its ${expanded.size} expanded items " +
                        "(mission seq $first..${items.size - 1}); its polygon and settings are not kept"
                }
                else -> fields.field("type").fail("item type '$type' is neither SimpleItem nor ComplexItem")
            }
        }
        if (items.size > MissionValidation.MAX_ITEMS) mission.field("items").fail("a mission holds at most ${MissionValidation.MAX_ITEMS} items")
        val fence = top.optional("geoFence")?.obj()
        val rally = top.optional("rallyPoints")?.obj()
        return QgcPlan(
            mission = items,
            geoFence = PlanGeoFence(
                polygons = fence?.optional("polygons")?.array()?.map { polygon(it.obj()) }.orEmpty(),
                circles = fence?.optional("circles")?.array()?.map { circle(it.obj()) }.orEmpty(),
            ),
            rallyPoints = rally?.optional("points")?.array()?.map { position(it) }.orEmpty(),
            plannedHome = mission.optional("plannedHomePosition")?.let { position(it) },
            firmwareType = mission.optional("firmwareType")?.int(0, 255) ?: 0,
            vehicleType = mission.optional("vehicleType")?.int(0, 255) ?: 0,
            cruiseSpeed = mission.optional("cruiseSpeed")?.double(),
            hoverSpeed = mission.optional("hoverSpeed")?.double(),
            groundStation = top.optional("groundStation")?.string() ?: "",
            itemExtras = itemExtras,
            missionExtras = JsonObject(mission.json.filterKeys { it !in missionKeys }),
            extras = JsonObject(top.json.filterKeys { it !in rootKeys }),
            warnings = warnings,
        )
    }

    private fun simple(fields: ObjectNode, items: MutableList<MissionItem>, extras: MutableMap<Int, JsonObject>, warnings: MutableList<String>) {
        val seq = items.size
        val frame = fields.field("frame").int(0, 255)
        val params = fields.field("params").array()
        if (params.size != 7) fields.field("params").fail("expected 7 params, found ${params.size}")
        items += MissionItem(
            seq = seq,
            frame = frame,
            command = fields.field("command").int(0, 65_535),
            autocontinue = fields.optional("autoContinue")?.boolean() ?: true,
            param1 = params[0].float(),
            param2 = params[1].float(),
            param3 = params[2].float(),
            param4 = params[3].float(),
            x = params[4].coordinate(frame, latitude = true),
            y = params[5].coordinate(frame, latitude = false),
            z = params[6].float(),
            missionType = MissionType.MISSION,
        )
        // QGC's AltitudeModeCalcAboveTerrain (3): the file holds the height above terrain ("Altitude")
        // and a null altitude param; QGC sends terrain + height AMSL, from its terrain tiles, only
        // when it uploads (QGroundControl MissionItem / SimpleMissionItem, AltMode enum).
        val altitudeMode = fields.optional("AltitudeMode")?.json
        if (altitudeMode == JsonPrimitive(ALT_MODE_CALC_ABOVE_TERRAIN) && items.last().z.isNaN()) {
            val height = fields.optional("Altitude")?.json?.let { (it as? JsonPrimitive)?.content } ?: "?"
            warnings += "${fields.path}: altitude $height m above terrain, which QGC calculates from its terrain data as it " +
                "uploads (AltitudeMode 3); the file holds no altitude for it, so it cannot be uploaded as it is"
        }
        // doJumpId is QGC's 1-based numbering: kept only where it differs from what writing would produce.
        val kept = fields.json.filter { (key, value) ->
            key !in itemKeys && !(key == "doJumpId" && value == JsonPrimitive(seq + 1))
        }
        if (kept.isNotEmpty()) extras[seq] = JsonObject(kept)
    }

    private fun polygon(fields: ObjectNode): FencePolygon {
        val vertices = fields.field("polygon").array().map { point(it) }
        if (vertices.size < 3) fields.field("polygon").fail("a fence polygon needs at least 3 vertices, found ${vertices.size}")
        return FencePolygon(fields.field("inclusion").boolean(), vertices)
    }

    private fun circle(fields: ObjectNode): FenceCircle {
        val circle = fields.field("circle").obj()
        val radius = circle.field("radius").double()
        if (radius <= 0) circle.field("radius").fail("radius $radius m must be > 0")
        return FenceCircle(fields.field("inclusion").boolean(), point(circle.field("center")), radius)
    }

    private fun point(node: Node): PlanPoint {
        val pair = node.array()
        if (pair.size != 2) node.fail("expected [latitude, longitude], found ${pair.size} values")
        return PlanPoint(pair[0].degrees(90.0), pair[1].degrees(180.0))
    }

    private fun position(node: Node): PlanPosition {
        val triple = node.array()
        if (triple.size != 3) node.fail("expected [latitude, longitude, altitude], found ${triple.size} values")
        val altitude = if (triple[2].json is JsonNull) Double.NaN else triple[2].double()
        return PlanPosition(triple[0].degrees(90.0), triple[1].degrees(180.0), altitude)
    }

    /** A JSON value and where it is, so that every failure can name it. */
    private open class Node(val path: String, open val json: JsonElement) {
        fun fail(reason: String): Nothing = throw QgcPlanFormatException(path, reason)

        fun obj(): ObjectNode = ObjectNode(path, json as? JsonObject ?: fail("expected an object, found ${kind()}"))

        fun array(): List<Node> {
            val array = json as? JsonArray ?: fail("expected an array, found ${kind()}")
            return array.mapIndexed { index, element -> Node("$path[$index]", element) }
        }

        fun primitive(): JsonPrimitive = json as? JsonPrimitive ?: fail("expected a value, found ${kind()}")

        fun string(): String = primitive().takeIf { it.isString }?.content ?: fail("expected a string, found ${kind()}")

        fun boolean(): Boolean = primitive().takeIf { !it.isString }?.content?.toBooleanStrictOrNull()
            ?: fail("expected true or false, found ${kind()}")

        fun decimal(): BigDecimal {
            val value = primitive()
            if (value.isString || value is JsonNull) fail("expected a number, found ${kind()}")
            val number = value.content.toBigDecimalOrNull() ?: fail("expected a number, found ${kind()}")
            // 1e999999999 or 1e-999999999 would make scaling crawl; beyond ±1e300 no field of a plan makes sense.
            val digitsBeforePoint = number.precision().toLong() - number.scale()
            if (digitsBeforePoint > 300) fail("${value.content} is out of range")
            return if (digitsBeforePoint < -300) BigDecimal.ZERO else number
        }

        fun int(min: Int, max: Int): Int {
            val value = decimal()
            val whole = value.stripTrailingZeros().takeIf { it.scale() <= 0 }?.toBigInteger()
                ?: fail("expected an integer, found $value")
            if (whole < min.toBigInteger() || whole > max.toBigInteger()) fail("$whole is outside $min..$max")
            return whole.toInt()
        }

        fun double(): Double {
            decimal()
            // The text itself, not the BigDecimal: BigDecimal has no -0.
            val value = primitive().content.toDouble()
            if (!value.isFinite()) fail("${primitive().content} is outside the Double range")
            return value
        }

        fun degrees(limit: Double): Double {
            val value = double()
            if (value !in -limit..limit) fail("$value° is outside ±$limit°")
            return value
        }

        /** A param: null is QGC's NaN. */
        fun float(): Float {
            if (json is JsonNull) return Float.NaN
            val value = double().toFloat()
            if (value.isInfinite()) fail("${primitive().content} is outside the Float range")
            return value
        }

        /** Param 5 or 6 as the MISSION_ITEM_INT integer for [frame]; null (NaN) reads as 0. */
        fun coordinate(frame: Int, latitude: Boolean): Int {
            if (json is JsonNull) return 0
            val value = decimal()
            val global = frame in MissionItem.GLOBAL_FRAMES
            if (global) {
                val limit = if (latitude) 90 else 180
                if (value.abs() > BigDecimal(limit)) fail("$value° is outside ±$limit°")
            }
            val decimals = when {
                global -> 7
                frame in MissionItem.LOCAL_FRAMES -> 4
                else -> 0
            }
            if (value.abs() > BigDecimal(1e12)) fail("$value does not fit MISSION_ITEM_INT")
            val units = value.movePointRight(decimals).setScale(0, RoundingMode.HALF_UP)
            if (units < Int.MIN_VALUE.toBigDecimal() || units > Int.MAX_VALUE.toBigDecimal()) fail("$value does not fit MISSION_ITEM_INT")
            if (decimals == 0 && value.compareTo(units) != 0) fail("$value must be a whole number in frame $frame")
            return units.toInt()
        }

        fun kind(): String = when (val value = json) {
            is JsonObject -> "an object"
            is JsonArray -> "an array"
            is JsonNull -> "null"
            is JsonPrimitive -> if (value.isString) "the string \"${value.content.take(40)}\"" else value.content
        }
    }

    private class ObjectNode(path: String, override val json: JsonObject) : Node(path, json) {
        fun optional(key: String): Node? = json[key]?.let { Node(child(key), it) }

        fun field(key: String): Node = optional(key) ?: fail("missing \"$key\"")

        private fun child(key: String) = if (path.isEmpty()) key else "$path.$key"
    }
}
