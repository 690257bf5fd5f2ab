package pod.launch.geo

import kotlinx.serialization.SerializationException
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.add
import kotlinx.serialization.json.booleanOrNull
import kotlinx.serialization.json.buildJsonArray
import kotlinx.serialization.json.buildJsonObject
import kotlinx.serialization.json.doubleOrNull
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import kotlinx.serialization.json.put
import kotlinx.serialization.json.putJsonArray
import kotlinx.serialization.json.putJsonObject
import pod.core.PodException
import pod.core.units.Location
import pod.core.units.m

/**
 * GeoJSON (RFC 7946) for [GeoFeature]s: a FeatureCollection of Points, LineStrings and Polygons.
 * Positions are `[longitude, latitude, altitude]` (the RFC's order, altitude in metres: here above
 * mean sea level); a polygon's ring is closed (its first position repeated at the end), as the RFC
 * requires, and read back without the repeat. A number property reads back as a Long when it is
 * integral, as a Double otherwise.
 */
public object GeoJson {
    private val json = Json { prettyPrint = true }

    /** [features] as a GeoJSON FeatureCollection. */
    public fun write(features: List<GeoFeature>): String = json.encodeToString(JsonObject.serializer(), buildJsonObject {
        put("type", "FeatureCollection")
        putJsonArray("features") {
            for (f in features) add(buildJsonObject {
                put("type", "Feature")
                putJsonObject("properties") {
                    f.properties.forEach { (key, value) ->
                        when (value) {
                            is String -> put(key, value)
                            is Boolean -> put(key, value)
                            else -> put(key, value as Number)
                        }
                    }
                }
                putJsonObject("geometry") {
                    when (val s = f.shape) {
                        is GeoShape.Point -> {
                            put("type", "Point")
                            put("coordinates", position(s.at))
                        }
                        is GeoShape.Line -> {
                            put("type", "LineString")
                            put("coordinates", JsonArray(s.points.map(::position)))
                        }
                        is GeoShape.Polygon -> {
                            put("type", "Polygon")
                            putJsonArray("coordinates") { add(JsonArray((s.vertices + s.vertices.first()).map(::position))) }
                        }
                    }
                }
            })
        }
    })

    /** The features of a GeoJSON FeatureCollection (or of a single Feature); throws [GeoJsonException] naming what is wrong. */
    public fun read(text: String): List<GeoFeature> {
        val root = try {
            Json.parseToJsonElement(text).jsonObject
        } catch (e: SerializationException) {
            throw GeoJsonException("not JSON: ${e.message?.lineSequence()?.first()}")
        } catch (e: IllegalArgumentException) {
            throw GeoJsonException("not a JSON object")
        }
        return when (root.string("type", "the document")) {
            "FeatureCollection" -> (root["features"] as? JsonArray ?: throw GeoJsonException("a FeatureCollection needs a features array"))
                .mapIndexed { i, f -> feature(f as? JsonObject ?: throw GeoJsonException("feature $i is not an object"), "feature $i") }
            "Feature" -> listOf(feature(root, "the feature"))
            else -> throw GeoJsonException("expected a FeatureCollection or a Feature, was ${root["type"]}")
        }
    }

    private fun position(l: Location): JsonArray = buildJsonArray {
        add(l.longitude)
        add(l.latitude)
        add(l.altitude.meters)
    }

    private fun feature(f: JsonObject, where: String): GeoFeature {
        val geometry = f["geometry"] as? JsonObject ?: throw GeoJsonException("$where has no geometry")
        val coordinates = geometry["coordinates"] ?: throw GeoJsonException("$where's geometry has no coordinates")
        val shape = try {
            when (val type = geometry.string("type", "$where's geometry")) {
                "Point" -> GeoShape.Point(location(coordinates, where))
                "LineString" -> GeoShape.Line(coordinates.jsonArray.map { location(it, where) })
                "Polygon" -> {
                    val ring = coordinates.jsonArray.firstOrNull()?.jsonArray?.map { location(it, where) } ?: throw GeoJsonException("$where's polygon has no ring")
                    GeoShape.Polygon(if (ring.size > 1 && ring.first() == ring.last()) ring.dropLast(1) else ring)
                }
                else -> throw GeoJsonException("$where: geometry type $type is not supported (Point, LineString, Polygon)")
            }
        } catch (e: IllegalArgumentException) {
            throw GeoJsonException("$where: ${e.message}")
        }
        val properties = (f["properties"] as? JsonObject).orEmpty().mapNotNull { (key, value) ->
            val p = value as? JsonPrimitive ?: return@mapNotNull null
            if (p is JsonNull) return@mapNotNull null
            key to (if (p.isString) p.content else p.booleanOrNull ?: p.content.toLongOrNull() ?: p.doubleOrNull ?: p.content)
        }.toMap()
        return GeoFeature(shape, properties)
    }

    private fun location(e: JsonElement, where: String): Location {
        val p = (e as? JsonArray)?.map { it.jsonPrimitive.doubleOrNull } ?: throw GeoJsonException("$where: a position must be an array of numbers")
        if (p.size < 2 || p.any { it == null }) throw GeoJsonException("$where: a position needs a longitude and a latitude, was $e")
        return Location(latitude = p[1]!!, longitude = p[0]!!, altitude = (p.getOrNull(2) ?: 0.0).m)
    }

    private fun JsonObject.string(key: String, where: String): String =
        (this[key] as? JsonPrimitive)?.takeIf { it.isString }?.content ?: throw GeoJsonException("$where needs a \"$key\" string")
}

/** A GeoJSON document Pod cannot read, and why. */
public class GeoJsonException(message: String) : PodException("GeoJSON: $message")
