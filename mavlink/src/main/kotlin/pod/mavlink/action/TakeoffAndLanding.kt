package pod.mavlink.action

import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.units.Distance
import pod.core.vehicle.isOnGround
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.MavCommands.DO_LAND_START
import pod.mavlink.command.MavCommands.NAV_LAND
import pod.mavlink.command.MavCommands.NAV_RETURN_TO_LAUNCH
import pod.mavlink.command.MavCommands.NAV_TAKEOFF
import pod.mavlink.command.VehicleCommand
import pod.mavlink.firmware.TakeOffWay
import pod.mavlink.telemetry.ModeRole
import kotlin.time.Duration

/**
 * Leaving and reaching the ground ([VehicleActions.takeoff], [VehicleActions.land],
 * [VehicleActions.returnToLaunch], [VehicleActions.awaitLanded]), each the way its autopilot and
 * airframe take it, confirmed by the height, mode or landed state the vehicle reports.
 */
internal class TakeoffAndLanding(
    private val vehicle: MavlinkVehicle,
    private val modes: ModeSwitch,
    private val waits: StateWaits,
    private val confirmTimeout: Duration,
) {
    /** Takes off to [altitude] above home and waits until it is reached or [timeout] passes. */
    suspend fun takeoff(altitude: Distance, timeout: Duration) {
        // PX4 accepts NAV_TAKEOFF disarmed and sits in Takeoff mode on the ground (commander's
        // VEHICLE_CMD_NAV_TAKEOFF only changes the mode; it never arms), and ArduCopter refuses it
        // with a bare FAILED (Mode::do_user_takeoff): say so before changing anything.
        waits.requireArmed("take off")
        when (vehicle.firmware().takeOffWay) {
            TakeOffWay.COMMAND_ANYWHERE -> {
                val home = awaitHomeAltitude()
                vehicle.commands.send(VehicleCommand(NAV_TAKEOFF, param4 = Float.NaN, param5 = Double.NaN, param6 = Double.NaN, param7 = (home + altitude.meters).toFloat()))
            }
            TakeOffWay.TAKEOFF_MODE -> {
                vehicle.params.write("TKOFF_ALT", altitude.meters)
                modes.setMode(vehicle.modeFor(ModeRole.TAKEOFF))
            }
            TakeOffWay.COMMAND_IN_GUIDED -> {
                modes.setMode(vehicle.modeFor(ModeRole.GUIDED))
                try {
                    vehicle.commands.send(VehicleCommand(NAV_TAKEOFF, param7 = altitude.meters.toFloat()))
                } catch (e: CommandRejected) {
                    // A resend after a lost ack is refused by a copter already climbing: that is success.
                    if (e.attempts == 1 || !waits.leavingGround()) throw e
                }
            }
        }
        val tolerance = maxOf(1.0, altitude.meters * 0.05)
        waits.confirm("takeoff to $altitude", "altitude ≥ ${altitude.meters - tolerance} m", vehicle.telemetry.position, timeout, untilDisarmed = true, describe = ::heightText) {
            it != null && it.relativeAltitude.meters >= altitude.meters - tolerance
        }
    }

    /** Lands: a multicopter where it is, an ArduPilot plane through a landing sequence; returns once it has begun. */
    suspend fun land() {
        if (vehicle.firmware().landsThroughLandingSequence) {
            try {
                vehicle.commands.send(VehicleCommand(DO_LAND_START))
            } catch (e: CommandRejected) {
                if (e.statusTexts.none { it.contains("No landing sequence", ignoreCase = true) }) throw e
                PlaneLanding.plan(vehicle)
                modes.setMode(vehicle.modeFor(ModeRole.MISSION))
            }
            waits.confirmMode("land", ModeRole.MISSION)
        } else {
            vehicle.commands.send(VehicleCommand(NAV_LAND, param4 = Float.NaN, param5 = Double.NaN, param6 = Double.NaN))
            waits.confirmMode("land", ModeRole.LAND)
        }
    }

    /** Returns to launch (NAV_RETURN_TO_LAUNCH), confirmed by the return mode. */
    suspend fun returnToLaunch() {
        vehicle.commands.send(VehicleCommand(NAV_RETURN_TO_LAUNCH))
        waits.confirmMode("return to launch", ModeRole.RETURN)
    }

    /** Waits until the vehicle is on the ground and disarmed. */
    suspend fun awaitLanded(timeout: Duration) {
        val t = vehicle.telemetry
        waits.confirm("landing", "on the ground and disarmed", combine(t.landedState, t.armed, t.position) { l, a, p -> Triple(l, a, p?.relativeAltitude) }, timeout, describe = { "${it.first.name.lowercase()}, ${if (it.second) "armed" else "disarmed"}" }) {
            isOnGround(it.first, it.third) && !it.second
        }
    }

    /**
     * Home's altitude above sea level, waiting up to the confirmation timeout for HOME_POSITION or
     * a GLOBAL_POSITION_INT to tell it: a command run as soon as a vehicle is heard comes before them.
     */
    private suspend fun awaitHomeAltitude(): Double = homeAltitude() ?: withTimeoutOrNull(confirmTimeout) {
        combine(vehicle.telemetry.home, vehicle.telemetry.position) { _, _ -> homeAltitude() }.first { it != null }
    } ?: throw VehicleNotReady(vehicle.systemId, "its home altitude (no HOME_POSITION or GLOBAL_POSITION_INT heard)", confirmTimeout, "take off")

    private fun homeAltitude(): Double? =
        vehicle.telemetry.home.value?.altitude?.meters
            ?: vehicle.telemetry.position.value?.let { it.location.altitude.meters - it.relativeAltitude.meters }
}
