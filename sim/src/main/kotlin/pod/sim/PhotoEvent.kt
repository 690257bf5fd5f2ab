package pod.sim

import pod.core.units.Location
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
)
