package pod.core.survey

import pod.core.units.Distance
import pod.core.units.Location

/** How the camera is fired along the tracks. */
public enum class CameraTrigger {
    /**
     * The camera fires every trigger distance by itself (MAV_CMD_DO_SET_CAM_TRIGG_DIST): on at a
     * track's start waypoint, off at its end. Each track has just its start and end waypoints
     * (plus the turnaround points); only the start is marked [SurveyWaypoint.photo] (the first
     * photo fires there).
     */
    DISTANCE,

    /**
     * A photo at each waypoint: every track is cut into equal legs of at most the trigger distance
     * (`ceil(length ÷ trigger distance)` legs), and every track waypoint from start to end, both
     * included, is marked [SurveyWaypoint.photo]. Turnaround points take no photo.
     */
    PER_WAYPOINT,
}

/** One waypoint of a polygon survey, in flying order. */
public data class SurveyWaypoint(
    /** Where: latitude and longitude, altitude = the survey height above home. */
    public val location: Location,
    /** Index of the track this waypoint belongs to, 0 for the first track flown. */
    public val track: Int,
    /** True where the photographed part of the track begins (the camera starts). */
    public val trackStart: Boolean,
    /** True where the photographed part of the track ends (the camera stops). */
    public val trackEnd: Boolean,
    /** True for the turnaround extensions before a track start and after a track end. */
    public val turnaround: Boolean,
    /** True where a photo is taken at the waypoint itself (see [CameraTrigger]). */
    public val photo: Boolean,
    /**
     * True for a bend of the transit from one track to the next (the [track] it leads to), at a
     * polygon vertex, where a straight leg would cut across the outside of a concave polygon.
     */
    public val transit: Boolean = false,
)

/**
 * A planned polygon survey: [waypoints] in flying order and the figures derived on the way.
 * Lengths are measured on the local flat frame the planner works in.
 */
public data class SurveyPlan(
    /** The waypoints, in flying order. */
    public val waypoints: List<SurveyWaypoint>,
    /** Distance between neighbouring tracks. */
    public val spacing: Distance,
    /** Distance between photos along a track. */
    public val triggerDistance: Distance,
    /** The ground one photo covers, when the spacing came from a camera. */
    public val footprint: Footprint?,
    /** Ground sampling distance (ground per pixel), when the spacing came from a camera. */
    public val groundSamplingDistance: Distance?,
    /** How many tracks (photographed passes) the survey flies. */
    public val trackCount: Int,
    /** Length of the photographed parts of the tracks, summed. */
    public val trackLength: Distance,
    /** Length of the whole path through the waypoints, turnarounds and transits included. */
    public val totalLength: Distance,
    /** Area of the polygon, in square metres. */
    public val areaSquareMeters: Double,
) {
    /** The waypoint locations alone, in flying order. */
    public val locations: List<Location> get() = waypoints.map { it.location }
}
