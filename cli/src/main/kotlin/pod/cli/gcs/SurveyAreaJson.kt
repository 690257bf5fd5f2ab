package pod.cli.gcs

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import pod.cli.json.SurveyPath
import pod.cli.json.SurveyPathPoint
import pod.cli.json.SurveyPoint
import pod.core.survey.Camera
import pod.core.survey.CameraTrigger
import pod.core.survey.PolygonSurvey
import pod.core.survey.SurveyPlan
import pod.core.survey.SurveySpacing
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.mavlink.MavlinkVehicle

/** A corner of the operator's polygon, in degrees. */
@Serializable
public data class LatLon(val lat: Double, val lon: Double)

/**
 * A survey camera as the page gives it (`pod.core.survey.Camera` and its overlaps): sensor size and
 * focal length in millimetres, image size in pixels, overlaps as fractions in [0, 1).
 */
@Serializable
public data class CameraJson(
    @SerialName("sensor_width_mm") val sensorWidthMm: Double,
    @SerialName("sensor_height_mm") val sensorHeightMm: Double,
    @SerialName("focal_length_mm") val focalLengthMm: Double,
    @SerialName("image_width") val imageWidth: Int,
    @SerialName("image_height") val imageHeight: Int,
    @SerialName("front_overlap") val frontOverlap: Double = 0.7,
    @SerialName("side_overlap") val sideOverlap: Double = 0.6,
)

/**
 * What the operator drew and chose: the [polygon] (at least 3 corners, simple), the [height] above
 * home in metres, and either the track [spacing] in metres or a [camera] to derive it from; the
 * tracks' compass [trackAngle] in degrees (0: north–south).
 */
@Serializable
public data class SurveyAreaJson(
    val polygon: List<LatLon>,
    val height: Double,
    val spacing: Double? = null,
    val camera: CameraJson? = null,
    @SerialName("track_angle") val trackAngle: Double = 0.0,
) {
    /**
     * The photo-at-every-waypoint survey of this area for [vehicle], entered nearest its home
     * (where it takes off). Checks what the planner does not: corners on the map, a height and a
     * spacing a survey flies at, and an area within reach of home; then the planner's own checks
     * (fewer than 3 corners, a self-intersecting polygon) say what is wrong.
     */
    internal fun plan(vehicle: MavlinkVehicle): SurveyPlan {
        val home = vehicle.telemetry.home.value ?: vehicle.telemetry.position.value?.location
            ?: throw GcsRequestException("vehicle ${vehicle.systemId} has no home or position yet: a survey is planned from its home")
        require(polygon.size >= 3) { "survey polygon needs at least 3 points, was ${polygon.size}" }
        require(polygon.size <= MAX_CORNERS) { "survey polygon has ${polygon.size} corners: at most $MAX_CORNERS" }
        polygon.forEachIndexed { i, p ->
            require(p.lat.isFinite() && p.lon.isFinite() && p.lat in -90.0..90.0 && p.lon in -180.0..180.0) { "corner $i is not on the map: ${p.lat}, ${p.lon}" }
        }
        require(height.isFinite() && height in MIN_HEIGHT..MAX_HEIGHT) { "height must be in $MIN_HEIGHT..$MAX_HEIGHT m, was $height" }
        val corners = polygon.map { Location(it.lat, it.lon) }
        val far = corners.withIndex().maxBy { home.distanceTo(it.value).meters }
        val reach = home.distanceTo(far.value).meters
        require(reach <= MAX_REACH) { "survey polygon too large: corner ${far.index} is ${reach.toInt()} m from home (at most ${MAX_REACH.toInt()} m)" }
        val plan = PolygonSurvey.plan(corners, height.m, spacing(), trackAngle.deg, start = home, trigger = CameraTrigger.PER_WAYPOINT)
        require(plan.waypoints.size <= MAX_WAYPOINTS) {
            "survey too large: ${plan.waypoints.size} waypoints (at most $MAX_WAYPOINTS): widen the spacing or shrink the polygon"
        }
        return plan
    }

    private fun spacing(): SurveySpacing {
        val c = camera
        if (c != null) {
            val camera = Camera(c.sensorWidthMm.div(1000).m, c.sensorHeightMm.div(1000).m, c.focalLengthMm.div(1000).m, c.imageWidth, c.imageHeight)
            return SurveySpacing.FromCamera(camera, height.m, c.frontOverlap, c.sideOverlap)
        }
        val s = spacing ?: throw GcsRequestException("give a spacing in metres or a camera")
        require(s.isFinite() && s in MIN_SPACING..MAX_SPACING) { "spacing must be in $MIN_SPACING..$MAX_SPACING m, was $s" }
        return SurveySpacing.Direct(s.m)
    }

    /** [plan] of this area as the page draws it; [eventId] is its build's (0: only planned). */
    internal fun pathEvent(sysid: Int, eventId: Long, plan: SurveyPlan) = SurveyPath(
        sysid, eventId,
        polygon.map { SurveyPoint(it.lat, it.lon) },
        plan.waypoints.map { SurveyPathPoint(it.location.latitude, it.location.longitude, it.photo) },
        height, plan.trackCount, plan.spacing.meters, plan.totalLength.meters, plan.areaSquareMeters,
    )

    private companion object {
        const val MAX_CORNERS = 100
        const val MIN_HEIGHT = 2.0
        const val MAX_HEIGHT = 300.0
        const val MIN_SPACING = 1.0
        const val MAX_SPACING = 1000.0

        /** The farthest a corner may lie from home: beyond it a multirotor's battery and the radio link give out. */
        const val MAX_REACH = 3000.0

        /** Waypoints of one survey: each is a goto and a photo, and the page draws them all. */
        const val MAX_WAYPOINTS = 2000
    }
}
