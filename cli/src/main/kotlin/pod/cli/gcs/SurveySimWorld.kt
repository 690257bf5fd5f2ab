package pod.cli.gcs

import pod.core.units.m
import pod.sim.SimVehicleConfig
import pod.sim.world.Rangefinder
import pod.sim.world.SimObject

/**
 * The world `pod gcs --sim` gives its vehicles, so that a survey drawn near home finds something:
 * [COUNT] objects scattered within [RADIUS_M] of each vehicle's home (the same [seed], the same
 * places relative to home) for its camera's photos to detect, and a downward rangefinder for the
 * backward pass to measure with. The ground is flat: the page has no terrain to show.
 */
public object SurveySimWorld {
    /** Objects per vehicle: about one per photo footprint of a survey flown 15–20 m up. */
    public const val COUNT: Int = 30

    /** How far from home they lie. */
    public const val RADIUS_M: Double = 60.0

    /** [config] with the objects and the rangefinder added, for `SimPlatform.start(configure = …)`. */
    public fun configure(seed: Long = 28): (SimVehicleConfig) -> SimVehicleConfig = { config ->
        config.copy(
            objects = SimObject.scatter(seed = seed, count = COUNT, center = config.home, radius = RADIUS_M.m),
            rangefinder = Rangefinder(),
        )
    }
}
