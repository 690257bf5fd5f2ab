package pod.core.mission

import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.Speed
import kotlin.time.Duration

/**
 * One step of a [Mission]. Steps that fly somewhere ([Navigation]) carry an absolute [Location]
 * whose altitude is a height above home; relative builder commands (move, moveFromHome, surveys)
 * are resolved to such locations when the mission is built.
 */
public sealed interface MissionStep {
    /** A step that flies the vehicle to (or around) [location]. */
    public sealed interface Navigation : MissionStep {
        /** Where the vehicle is when the step ends; its altitude is a height above home. */
        public val location: Location
    }

    /** A step that changes a setting or drives a payload without moving the vehicle. */
    public sealed interface Action : MissionStep

    /**
     * Take off and climb to [location]'s height (multirotors climb vertically; planes climb at [pitch]).
     *
     * @property pitch the climb angle a plane holds until it reaches the height; multirotors ignore it.
     */
    public data class TakeOff(override val location: Location, val pitch: Angle) : Navigation

    /**
     * Fly to [location] and stay there for [hold] (rotorcraft only; planes pass through).
     *
     * @property hold how long to stay once there; zero flies on at once.
     */
    public data class Waypoint(override val location: Location, val hold: Duration = Duration.ZERO) : Navigation

    /** Fly to [location] and circle it at [radius] for [duration]. */
    public data class Loiter(
        override val location: Location,
        /** Circle radius; positive is clockwise. */
        val radius: Distance,
        /** How long to circle. */
        val duration: LoiterDuration,
    ) : Navigation

    /** Land at [location] (its height is ignored), facing [yaw] if given. */
    public data class Land(
        override val location: Location,
        /** Heading to land with, or null to keep the current one (sent as NaN). */
        val yaw: Angle? = null,
        /** Whether to land on a precision target. */
        val precision: PrecisionLand = PrecisionLand.DISABLED,
    ) : Navigation

    /** Return to the launch point by the autopilot's own return-to-launch procedure (multirotors land there). */
    public data object ReturnHome : MissionStep

    /**
     * Change the [kind] of speed to [speed] for the steps that follow.
     *
     * @property kind which speed: air, ground, climb or descent.
     * @property speed the new value of that speed.
     */
    public data class ChangeSpeed(val kind: SpeedKind, val speed: Speed) : Action

    /**
     * Climb or descend to [height] above home, then go on.
     *
     * @property height the new height above home.
     */
    public data class ChangeAltitude(val height: Distance) : Action

    /**
     * Wait [duration] where the vehicle is before the next step.
     *
     * @property duration how long to wait.
     */
    public data class Delay(val duration: Duration) : Action

    /**
     * Start taking photos: [count] photos [interval] apart, or photos until [StopCapture] when
     * [count] is 0. One photo is `count = 1`.
     *
     * @property count how many photos, 0 for photos until [StopCapture].
     * @property interval the time between two photos.
     */
    public data class StartCapture(val count: Int, val interval: Duration) : Action

    /** Stop a capture started with `count = 0`. */
    public data object StopCapture : Action
}

/** How long a [MissionStep.Loiter] lasts. */
public sealed interface LoiterDuration {
    /** Until something else happens (the mission ends there). */
    public data object Unlimited : LoiterDuration

    /**
     * This many full circles.
     *
     * @property turns the number of full circles.
     */
    public data class Turns(val turns: Int) : LoiterDuration

    /**
     * This long, counted from arrival.
     *
     * @property time how long to circle once there.
     */
    public data class Time(val time: Duration) : LoiterDuration
}

/** Which speed a [MissionStep.ChangeSpeed] sets. */
public enum class SpeedKind {
    /** Airspeed (planes). */
    AIR,

    /** Speed over ground. */
    GROUND,

    /** Climb rate. */
    CLIMB,

    /** Descent rate. */
    DESCENT,
}

/** Whether a landing uses a precision-landing target. */
public enum class PrecisionLand {
    /** Ordinary landing. */
    DISABLED,

    /** Use a target when one is seen. */
    OPPORTUNISTIC,

    /** Search for a target and land on it. */
    REQUIRED,
}
