package pod.mavlink.plan

import kotlinx.serialization.json.JsonObject
import pod.mavlink.mission.MissionItem

/**
 * A .plan file that cannot be read: [path] names the JSON value (`mission.items[3].params[4]`) and
 * [reason] says what is wrong with it.
 */
public class QgcPlanFormatException(
    /** Where in the document the fault is, as a JSON path from the root (empty for the document itself). */
    public val path: String,
    /** Why the value was rejected. */
    public val reason: String,
) : pod.core.PodException(if (path.isEmpty()) "plan: $reason" else "plan $path: $reason")

/**
 * A latitude/longitude pair as a .plan file writes it: decimal degrees kept as the file's doubles (not rounded to
 * MAVLink's 10⁻⁷ degree) so that a plan read and written again prints the same numbers.
 */
public data class PlanPoint(
    /** Latitude in degrees, −90..90. */
    public val latitude: Double,
    /** Longitude in degrees, −180..180. */
    public val longitude: Double,
)

/** A position with altitude in metres, as .plan files hold the planned home (AMSL) and rally points (above home). */
public data class PlanPosition(
    /** Latitude in degrees, −90..90. */
    public val latitude: Double,
    /** Longitude in degrees, −180..180. */
    public val longitude: Double,
    /** Altitude in metres; NaN where the file wrote `null`. */
    public val altitude: Double,
)

/** A polygon fence: the vehicle must stay inside it ([inclusion]) or out of it. */
public data class FencePolygon(
    /** True for an inclusion (keep-in) fence, false for an exclusion (keep-out) zone. */
    public val inclusion: Boolean,
    /** The corners in file order (QGC draws them clockwise); at least three. */
    public val vertices: List<PlanPoint>,
)

/** A circular fence around [center] with [radiusMetres]. */
public data class FenceCircle(
    /** True for an inclusion (keep-in) fence, false for an exclusion (keep-out) zone. */
    public val inclusion: Boolean,
    /** The centre of the circle. */
    public val center: PlanPoint,
    /** The radius in metres, > 0. */
    public val radiusMetres: Double,
)

/** The geofence section of a plan: any number of polygons and circles, each inclusion or exclusion. */
public data class PlanGeoFence(
    /** The polygon fences in file order. */
    public val polygons: List<FencePolygon> = emptyList(),
    /** The circle fences in file order. */
    public val circles: List<FenceCircle> = emptyList(),
)

/**
 * A QGroundControl flight plan: mission, geofence, rally points and planned home, plus what Pod does not
 * interpret, kept so that reading and writing a plan loses nothing.
 *
 * [mission] holds the items as MISSION_ITEM_INT carries them (seq from 0, [MissionItem.missionType] MISSION):
 * QGC's simple items map one to one; a survey (complex item) arrives as the items it expands to, with a
 * [warnings] line saying so, and is written back as those items.
 */
public data class QgcPlan(
    /** The mission items, seq 0, 1, 2, … in file order. */
    public val mission: List<MissionItem> = emptyList(),
    /** The geofence polygons and circles. */
    public val geoFence: PlanGeoFence = PlanGeoFence(),
    /** The rally (safe landing) points; altitude is relative to home. */
    public val rallyPoints: List<PlanPosition> = emptyList(),
    /** Where the plan assumes home to be (altitude AMSL), or null when the file has none. */
    public val plannedHome: PlanPosition? = null,
    /** MAV_AUTOPILOT the plan was made for (3 ArduPilot, 12 PX4, 0 generic). */
    public val firmwareType: Int = 0,
    /** MAV_TYPE the plan was made for (1 fixed wing, 2 quadrotor, …). */
    public val vehicleType: Int = 0,
    /** QGC's default speed for fixed wings, m/s, or null when the file has none. */
    public val cruiseSpeed: Double? = null,
    /** QGC's default speed for multirotors, m/s, or null when the file has none. */
    public val hoverSpeed: Double? = null,
    /** The application that wrote the file. */
    public val groundStation: String = "Pod",
    /**
     * Per mission item (by seq), the item's fields Pod does not interpret (QGC's `Altitude`, `AltitudeMode`,
     * `AMSLAltAboveTerrain`, a `doJumpId` other than seq + 1, …); written back unchanged.
     */
    public val itemExtras: Map<Int, JsonObject> = emptyMap(),
    /** Fields of the `mission` object Pod does not interpret (`globalPlanAltitudeMode`, …). */
    public val missionExtras: JsonObject = JsonObject(emptyMap()),
    /** Top-level fields Pod does not interpret. */
    public val extras: JsonObject = JsonObject(emptyMap()),
    /** What reading changed or could not keep (a survey expanded to its items); empty for a plan Pod builds. */
    public val warnings: List<String> = emptyList(),
)
