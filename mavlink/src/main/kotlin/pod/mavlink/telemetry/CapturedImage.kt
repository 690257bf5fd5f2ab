package pod.mavlink.telemetry

import pod.core.units.Distance
import pod.core.units.Location

/** A photo the vehicle reports taken (CAMERA_IMAGE_CAPTURED, or ArduPilot's CAMERA_FEEDBACK). */
public data class CapturedImage(
    /** Its number since boot (image_index). */
    public val imageIndex: Int,
    /** Milliseconds since the vehicle booted when it was taken. */
    public val timeBootMs: Long,
    /** Where it was taken (altitude above mean sea level). */
    public val location: Location,
    /** Height above home where it was taken. */
    public val relativeAltitude: Distance,
    /** Whether the capture succeeded (capture_result 1). */
    public val success: Boolean,
    /** Where the image is, or what the vehicle says about it (file_url); empty when it says nothing. */
    public val fileUrl: String,
)
