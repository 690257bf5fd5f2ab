package pod.core.vehicle

import pod.core.platform.PlatformVehicle
import pod.core.units.Distance
import pod.core.units.m

/**
 * Whether a vehicle is off the ground: the one definition the engine's platforms, the MAVLink
 * executor and actions, and the samples share.
 *
 * Taking off, in the air and landing are airborne. So is a vehicle more than [CLEAR_OF_GROUND]
 * above home that is armed, or whose arming state the caller does not know ([armed] null), whatever
 * its landed state says: some autopilots do not report one (UNDEFINED) and any report can lag.
 * Disarmed, or on the ground and no higher than [CLEAR_OF_GROUND], it is not.
 */
public fun isAirborne(landed: LandedState, heightAboveHome: Distance?, armed: Boolean? = null): Boolean =
    landed == LandedState.TAKEOFF || landed == LandedState.IN_AIR || landed == LandedState.LANDING ||
        (armed != false && heightAboveHome != null && heightAboveHome > CLEAR_OF_GROUND)

/**
 * Whether a vehicle is on the ground: its landed state says so, or, while that is unknown
 * (UNDEFINED: an autopilot not streaming EXTENDED_SYS_STATE yet, or at all), it is no higher than
 * [CLEAR_OF_GROUND] above home.
 */
public fun isOnGround(landed: LandedState, heightAboveHome: Distance?): Boolean =
    landed == LandedState.ON_GROUND || (landed == LandedState.UNDEFINED && heightAboveHome != null && heightAboveHome <= CLEAR_OF_GROUND)

/** How far above home a vehicle must be for its height alone to say it is airborne (see [isAirborne]). */
public val CLEAR_OF_GROUND: Distance = 1.m

/** [isAirborne] for this vehicle, from its landed state and its height above home. */
public val PlatformVehicle.airborne: Boolean
    get() = isAirborne(landedState.value, position.value?.relativeAltitude)
