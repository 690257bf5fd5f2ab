package pod.dsl

import pod.core.mission.MissionStep
import pod.core.mission.SpeedKind
import pod.core.units.Speed
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

// Commands that change a setting or drive the camera without moving the vehicle, so they leave
// MissionBuilder.position as it is.

/**
 * Sets the given speeds for the steps that follow, one [MissionStep.ChangeSpeed] each: [air]
 * (planes), [ground], [climb] and [descent] rate. At least one must be given.
 */
public fun MissionBuilder.speed(air: Speed? = null, ground: Speed? = null, climb: Speed? = null, descent: Speed? = null) {
    val speeds = listOf(SpeedKind.AIR to air, SpeedKind.GROUND to ground, SpeedKind.CLIMB to climb, SpeedKind.DESCENT to descent)
    require(speeds.any { it.second != null }) { "speed: give at least one of air, ground, climb, descent" }
    for ((kind, speed) in speeds) {
        if (speed == null) continue
        requirePositive("speed", kind.name.lowercase(), speed, Speed.ZERO, MissionLimits.speed)
    }
    for ((kind, speed) in speeds) {
        if (speed != null) add(MissionStep.ChangeSpeed(kind, speed))
    }
}

/** Waits [duration] where the vehicle is before the next step. */
public fun MissionBuilder.delay(duration: Duration) {
    requireIn("delay", "duration", duration, MissionLimits.delay)
    add(MissionStep.Delay(duration))
}

/** Takes one photo. */
public fun MissionBuilder.capturePhoto() {
    add(MissionStep.StartCapture(1, Duration.ZERO))
}

/** Takes [count] photos, [interval] apart. */
public fun MissionBuilder.captureSeveralPhotos(count: Int, interval: Duration = 2.seconds) {
    requireIn("captureSeveralPhotos", "count", count, MissionLimits.photoCount)
    requirePositive("captureSeveralPhotos", "interval", interval, Duration.ZERO, MissionLimits.captureInterval)
    add(MissionStep.StartCapture(count, interval))
}

/** Takes a photo every [interval] until [stopCapturing]. */
public fun MissionBuilder.captureUntilStop(interval: Duration = 2.seconds) {
    requirePositive("captureUntilStop", "interval", interval, Duration.ZERO, MissionLimits.captureInterval)
    add(MissionStep.StartCapture(0, interval))
}

/** Stops a capture started with [captureUntilStop]. */
public fun MissionBuilder.stopCapturing() {
    add(MissionStep.StopCapture)
}
