package pod.launch.geo

import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.MavFrames
import pod.mavlink.mission.MissionItem
import pod.mavlink.plan.QgcPlan
import pod.mavlink.tlog.FlownTrack

/**
 * Plans and flown tracks as [GeoFeature]s, for GeoJSON, KML and the SVG map alike.
 *
 * Every feature says what it is in its `kind` property:
 * - `mission`: a Line through the mission's positioned items, in order (`items`: how many;
 *   `vehicle`: the system id of the vehicle that flies it, for a program's mission);
 * - `fence`: a Polygon, or for a circle a Point with a `radius` in metres; `inclusion` true for an
 *   area to stay inside, false for one to keep out of;
 * - `rally`: a Point;
 * - `home`: a Point, the plan's planned home or a vehicle's (`vehicle`: its system id);
 * - `track`: a Line, where a vehicle flew (`vehicle`: its system id).
 *
 * Altitudes are above mean sea level: a mission item relative to home is raised by the plan's home
 * altitude. Without a planned home, relative altitudes are kept as they are and the mission says
 * `altitude: "relative to home"`.
 */
public object MapFeatures {
    /** `kind` of a mission's path. */
    public const val MISSION: String = "mission"

    /** `kind` of a fence zone. */
    public const val FENCE: String = "fence"

    /** `kind` of a rally point. */
    public const val RALLY: String = "rally"

    /** `kind` of a home, planned or a vehicle's. */
    public const val HOME: String = "home"

    /** Property of a mission line: its points' item numbers, comma separated. */
    public const val NUMBERS: String = "numbers"

    /** `kind` of a flown track. */
    public const val TRACK: String = "track"

    /** The features of [plan]: its mission, fence zones, rally points and planned home; the mission is called [name]. */
    public fun of(plan: QgcPlan, name: String = "mission"): List<GeoFeature> = buildList {
        // A file may write an altitude as null (read as NaN): GeoJSON has no NaN, so it is drawn at 0.
        // A home at 0°, 0° is one its writer did not know (Pod before issue 25 wrote [0, 0, 0]): not drawn.
        val home = plan.plannedHome?.takeUnless { it.latitude == 0.0 && it.longitude == 0.0 }
            ?.let { Location(it.latitude, it.longitude, it.altitude.orZero().m) }
        addAll(mission(plan.mission, name, home, numberShift = 1))
        plan.geoFence.polygons.forEachIndexed { i, p ->
            val vertices = p.vertices.map { Location(it.latitude, it.longitude) }
            // QGC stores a polygon open; a file that closes it anyway is drawn the same.
            val open = if (vertices.size > 3 && vertices.first() == vertices.last()) vertices.dropLast(1) else vertices
            if (open.size >= 3) add(GeoFeature(GeoShape.Polygon(open), mapOf("kind" to FENCE, "name" to "fence ${i + 1}", "inclusion" to p.inclusion)))
        }
        plan.geoFence.circles.forEachIndexed { i, c ->
            val centre = Location(c.center.latitude, c.center.longitude)
            add(GeoFeature(GeoShape.Point(centre), mapOf("kind" to FENCE, "name" to "fence circle ${i + 1}", "inclusion" to c.inclusion, "radius" to c.radiusMetres)))
        }
        plan.rallyPoints.forEachIndexed { i, r ->
            add(GeoFeature(GeoShape.Point(Location(r.latitude, r.longitude, (r.altitude.orZero() + (home?.altitude?.meters ?: 0.0)).m)), mapOf("kind" to RALLY, "name" to "rally ${i + 1}")))
        }
        if (home != null) add(GeoFeature(GeoShape.Point(home), mapOf("kind" to HOME, "name" to "planned home")))
    }

    /**
     * A mission's path as a feature (none when fewer than two items have a position): the items
     * in a global frame that fly to a place, their altitudes made absolute with [home] when given,
     * each numbered by its seq plus [numberShift] (1 for a .plan's items, which QGC lists from 1).
     */
    public fun mission(items: List<MissionItem>, name: String = "mission", home: Location? = null, numberShift: Int = 0): List<GeoFeature> {
        val flown = items.filter { it.isGlobal && it.command in NAVIGATION && !(it.x == 0 && it.y == 0) }
        val points = flown.map { item ->
            val relative = item.frame !in ABSOLUTE_FRAMES
            val base = if (relative && home != null) home.altitude.meters else 0.0
            Location(item.latitude, item.longitude, (item.z.toDouble().orZero() + base).m)
        }
        if (points.size < 2) return emptyList()
        val properties = buildMap<String, Any> {
            put("kind", MISSION)
            put("name", name)
            put("items", points.size.toLong())
            // Each point's mission item number, as a ground station lists them (a plan's from 1, a WPL file's as its lines say).
            put(NUMBERS, flown.joinToString(",") { (it.seq + numberShift).toString() })
            if (home == null && items.any { it.isGlobal && it.frame !in ABSOLUTE_FRAMES }) put("altitude", "relative to home")
        }
        return listOf(GeoFeature(GeoShape.Line(points), properties))
    }

    /** [track] as a `track` line (when it has two points or more) and its home, if known. */
    public fun of(track: FlownTrack): List<GeoFeature> =
        track(track.systemId, track.name, track.points) + listOfNotNull(track.home?.let { home(track.systemId, track.name, it) })

    /** Where vehicle [vehicleId], called [name], flew: a `track` line, none for fewer than two [points]. */
    public fun track(vehicleId: Int, name: String, points: List<Location>): List<GeoFeature> =
        if (points.size < 2) emptyList() else listOf(GeoFeature(GeoShape.Line(points), mapOf("kind" to TRACK, "name" to name, "vehicle" to vehicleId.toLong())))

    /** The home of vehicle [vehicleId], called [name]. */
    public fun home(vehicleId: Int, name: String, at: Location): GeoFeature =
        GeoFeature(GeoShape.Point(at), mapOf("kind" to HOME, "name" to "home of $name", "vehicle" to vehicleId.toLong()))

    /** The path [mission] plans for vehicle [vehicleId]: a `mission` line through its navigation steps (none for fewer than two). */
    public fun planned(vehicleId: Int, mission: Mission): List<GeoFeature> {
        val points = mission.steps.filterIsInstance<MissionStep.Navigation>().map { it.location }
        if (points.size < 2) return emptyList()
        return listOf(GeoFeature(GeoShape.Line(points), mapOf("kind" to MISSION, "name" to mission.name, "items" to points.size.toLong(), "vehicle" to vehicleId.toLong())))
    }

    private fun Double.orZero() = if (isFinite()) this else 0.0

    /** MAV_CMD numbers of items that fly to their position (waypoint, loiters, land, take-off, spline, VTOL, payload place). */
    private val NAVIGATION = setOf(16, 17, 18, 19, 21, 22, 31, 82, 84, 85, 94)

    /** Frames whose altitude is above mean sea level already. */
    private val ABSOLUTE_FRAMES = setOf(MavFrames.GLOBAL, MavFrames.GLOBAL_INT)
}
