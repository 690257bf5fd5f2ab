package pod.sim.world

import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.deg
import pod.core.units.m
import kotlin.math.atan

/**
 * The simulated camera's field of view. The camera looks straight down (nadir, no gimbal) and is
 * fixed to the airframe with the top of the image towards the vehicle's heading: [horizontal]
 * spans left to right across the heading, [vertical] spans front to back along it. Its ground
 * footprint is therefore a rectangle turned with the vehicle's heading.
 */
public data class CameraFov(
    /** Full angle across the heading (the image's width). */
    public val horizontal: Angle,
    /** Full angle along the heading (the image's height). */
    public val vertical: Angle,
) {
    init {
        require(horizontal.degrees > 0 && horizontal.degrees < 180) { "horizontal must be in (0°, 180°), was $horizontal" }
        require(vertical.degrees > 0 && vertical.degrees < 180) { "vertical must be in (0°, 180°), was $vertical" }
    }

    /** Fields of view from a camera's sensor and lens. */
    public companion object {
        /** The field of view of a pinhole camera with a [sensorWidth] × [sensorHeight] sensor behind a [focalLength] lens. */
        public fun fromSensor(sensorWidth: Distance, sensorHeight: Distance, focalLength: Distance): CameraFov {
            require(sensorWidth.meters > 0 && sensorHeight.meters > 0) { "sensor size must be > 0, was $sensorWidth × $sensorHeight" }
            require(focalLength.meters > 0) { "focalLength must be > 0, was $focalLength" }
            return CameraFov(
                Math.toDegrees(2 * atan(sensorWidth.meters / (2 * focalLength.meters))).deg,
                Math.toDegrees(2 * atan(sensorHeight.meters / (2 * focalLength.meters))).deg,
            )
        }

        /** A 1-inch 13.2 × 8.8 mm sensor behind an 8.8 mm lens (a common mapping camera): ~73.7° × 53.1°. */
        public val DEFAULT: CameraFov = fromSensor(0.0132.m, 0.0088.m, 0.0088.m)
    }
}
