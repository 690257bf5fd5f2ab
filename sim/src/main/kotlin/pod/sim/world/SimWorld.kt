package pod.sim.world

import pod.core.units.Location
import pod.sim.flight.northEast
import kotlin.math.abs
import kotlin.math.cos
import kotlin.math.sin
import kotlin.math.tan

/**
 * What a simulated vehicle's sensors see of the world: the ground under it ([terrain], or flat at
 * [flatGround] metres AMSL without one) and the [objects] its camera (if it has one) may photograph
 * through [fov].
 */
internal class SimWorld(
    val flatGround: Double,
    val terrain: Terrain? = null,
    val objects: List<SimObject> = emptyList(),
    val fov: CameraFov = CameraFov.DEFAULT,
    /** Whether it carries a camera at all (commands to a missing one are UNSUPPORTED). */
    val camera: Boolean = true,
) {
    /** Ground elevation AMSL in metres under [location]. */
    fun groundAt(location: Location): Double = terrain?.elevationMetres(location) ?: flatGround

    /**
     * The objects a nadir photo taken at [camera] (its altitude AMSL) with the vehicle heading
     * [headingDeg] shows: those whose offset, turned into the camera's frame, lies within the
     * field of view at the object's own depth below the camera (a pinhole camera looking straight
     * down sees a point at depth d within d·tan(fov/2) of its axis). Objects above the camera, or
     * hidden behind a hill, are not modelled: no occlusion.
     */
    fun detect(camera: Location, headingDeg: Double): List<SimObject> {
        if (objects.isEmpty()) return emptyList()
        val h = Math.toRadians(headingDeg)
        val halfAcross = tan(fov.horizontal.radians / 2)
        val halfAlong = tan(fov.vertical.radians / 2)
        return objects.filter { obj ->
            val depth = camera.altitude.meters - groundAt(obj.location)
            if (depth <= 0) return@filter false
            val (n, e) = northEast(camera, obj.location)
            val along = n * cos(h) + e * sin(h)
            val across = -n * sin(h) + e * cos(h)
            abs(along) <= depth * halfAlong && abs(across) <= depth * halfAcross
        }
    }
}
