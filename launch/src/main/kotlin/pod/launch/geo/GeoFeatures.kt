package pod.launch.geo

import pod.core.units.Location

/**
 * A shape on the map with its properties: what GeoJSON ([GeoJson]) and KML ([Kml]) export, and
 * GeoJSON reads back. Altitudes are above mean sea level, as in [Location].
 */
public data class GeoFeature(
    /** Where it is. */
    val shape: GeoShape,
    /** What it is: a name, a kind (`"mission"`, `"fence"`, `"rally"`, `"track"`), a vehicle id… Values are strings, numbers or booleans. */
    val properties: Map<String, Any> = emptyMap(),
) {
    init {
        properties.forEach { (key, value) ->
            require(value is String || value is Number || value is Boolean) { "property $key must be a string, number or boolean, was ${value::class.simpleName}" }
            require(value !is Double || value.isFinite()) { "property $key must be finite, was $value" }
        }
    }

    /** The `name` property, if any. */
    val name: String? get() = properties["name"] as? String
}

/** The geometry of a [GeoFeature]. */
public sealed interface GeoShape {
    /**
     * One place (a home, a rally point).
     *
     * @property at the place.
     */
    public data class Point(val at: Location) : GeoShape

    /**
     * A path (a mission, a flown track); at least 2 points.
     *
     * @property points the path's points, in order.
     * @throws IllegalArgumentException when there are fewer than 2 points.
     */
    public data class Line(val points: List<Location>) : GeoShape {
        init {
            require(points.size >= 2) { "a line needs at least 2 points, was ${points.size}" }
        }
    }

    /**
     * An area (a fence polygon); at least 3 vertices, not closed (the last is not the first).
     *
     * @property vertices the polygon's corners, in order, the first not repeated at the end.
     * @throws IllegalArgumentException when there are fewer than 3 vertices or the last repeats the first.
     */
    public data class Polygon(val vertices: List<Location>) : GeoShape {
        init {
            require(vertices.size >= 3) { "a polygon needs at least 3 vertices, was ${vertices.size}" }
            require(vertices.first() != vertices.last()) { "give a polygon's vertices without repeating the first at the end" }
        }
    }
}
