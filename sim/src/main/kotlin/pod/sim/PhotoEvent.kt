package pod.sim

import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.deg
import pod.sim.world.SimObject
import kotlin.time.Duration

/** A photo the simulated camera took. */
public data class PhotoEvent(
    /** Its number, from 0 since boot (CAMERA_IMAGE_CAPTURED's image_index). */
    public val index: Int,
    /** Simulated time since boot when it was taken. */
    public val time: Duration,
    /** Where the vehicle was. */
    public val location: Location,
    /** The mission item being executed, or null outside a mission. */
    public val missionSeq: Int?,
    /** The vehicle's heading, which turns the footprint (see [pod.sim.world.CameraFov]). */
    public val heading: Angle = 0.deg,
    /** Height of the camera above the terrain straight below it. */
    public val heightAboveGround: Distance? = null,
    /** The seeded objects inside the photo's footprint, by id (see [pod.sim.world.CameraFov] for the footprint). */
    public val detected: List<SimObject> = emptyList(),
)
