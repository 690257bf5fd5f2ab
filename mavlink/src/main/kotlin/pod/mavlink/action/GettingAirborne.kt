package pod.mavlink.action

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.units.Distance
import pod.core.vehicle.LandedState
import pod.core.vehicle.isAirborne
import pod.mavlink.MavlinkVehicle
import pod.mavlink.firmware.TakeOffWay
import pod.mavlink.telemetry.FlightModes
import pod.mavlink.telemetry.ModeRole

/**
 * The one way Pod gets a vehicle into the air, whatever state it was left in: freshly booted,
 * just landed, left in RTL, LAND, BRAKE or AUTO by an earlier flight. Every take-off goes through
 * it (`pod takeoff`, `pod start --arm`, `pod queue serve --takeoff`, missions, queue and survey
 * tasks), in this order:
 * 1. Is it flying? Judged from its landed state, and while that is unknown (UNDEFINED until
 *    EXTENDED_SYS_STATE is streamed) from its arming state and height ([isAirborne]).
 * 2. Into a mode it arms and takes off in *before* arming: an ArduCopter armed in STABILIZE whose
 *    switch to GUIDED is then refused ("requires position") would sit armed on the ground. Refusals
 *    that clear by waiting are waited out ([VehicleActions.setMode]).
 * 3. Arm, waiting out the refusals of a vehicle still initialising ([VehicleActions.arm]).
 * 4. Take off ([VehicleActions.takeoff]).
 * It says what it changed ([Step]s), so that a "STABILIZE → GUIDED" is never a surprise.
 */
internal class GettingAirborne(private val vehicle: MavlinkVehicle, private val actions: VehicleActions) {
    /** Flies up to [height] above home unless already flying; returns what it did, in order. */
    suspend fun takeOff(height: Distance, timeout: Duration): List<String> {
        if (flying()) return emptyList()
        val done = ArrayList<String>()
        done += prepare(takeoffMode())
        actions.takeoff(height, timeout)
        done += "took off to $height"
        return done
    }

    /**
     * Arms a vehicle on the ground for a flight that then changes mode itself (a mission start):
     * into [mode], or, when null, out of a mode it will not arm in into one it will. Returns what it did.
     */
    suspend fun armOnGround(mode: String?): List<String> = prepare(mode ?: armableNow())

    /** Switches to [mode] (null: stays) and arms; the steps it took. */
    private suspend fun prepare(mode: String?): List<String> {
        val done = ArrayList<String>()
        val before = vehicle.telemetry.mode.value?.name
        if (mode != null && mode != before) {
            actions.setMode(mode)
            done += "mode ${before ?: "?"} → $mode"
        }
        if (!vehicle.telemetry.armed.value) {
            actions.arm()
            done += "armed"
        }
        return done
    }

    /**
     * Whether the vehicle is off the ground, once its position has had a moment to arrive: the
     * landed state says so, or, while it is unknown, an armed vehicle higher than 1 m above home.
     */
    suspend fun flying(): Boolean {
        val t = vehicle.telemetry
        withTimeoutOrNull(STATE_WAIT) {
            combine(t.position, t.landedState) { p, l -> p != null && (l != LandedState.UNDEFINED || !t.armed.value) }.first { it }
        }
        return isAirborne(t.landedState.value, t.position.value?.relativeAltitude, t.armed.value)
    }

    /** The mode this autopilot takes off in from the ground. */
    private fun takeoffMode(): String? {
        val (autopilot, type) = vehicle.airframe()
        return when {
            // NAV_TAKEOFF in GUIDED (Mode::do_user_takeoff; has_user_takeoff in ArduCopter/mode.h).
            vehicle.firmware().takeOffWay == TakeOffWay.COMMAND_IN_GUIDED -> FlightModes.forRole(autopilot, type, ModeRole.GUIDED)
            // ArduPlane arms where it is, if it may, and then enters TAKEOFF ([VehicleActions.takeoff]);
            // PX4 arms in Hold and takes NAV_TAKEOFF.
            else -> armableNow()
        }
    }

    /** The mode to arm in now: the current one when the autopilot arms in it, else its hold mode. */
    private fun armableNow(): String? {
        val (autopilot, type) = vehicle.airframe()
        val current = vehicle.telemetry.mode.value?.name
        val firmware = vehicle.firmware()
        return if (current != null && firmware.armsIn(current)) null else FlightModes.forRole(autopilot, type, ModeRole.HOLD)?.takeIf {
            firmware.armsIn(it)
        } ?: FlightModes.forRole(autopilot, type, ModeRole.GUIDED)
    }

    private companion object {
        /** How long a freshly heard vehicle's position and landed state may take to arrive. */
        val STATE_WAIT = 3.seconds
    }
}
