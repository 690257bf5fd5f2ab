package pod.mavlink.action

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.VehicleLost
import pod.core.vehicle.isAirborne
import pod.mavlink.MavlinkVehicle
import pod.mavlink.telemetry.ModeRole
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * The waits that confirm an action: an acknowledgement says the vehicle took the command, only
 * its telemetry says it did it (armed, in the mode, at the height). Each wait ends as soon as the
 * vehicle shows it, and fails with what it showed last ([ActionNotConfirmed]), when it is lost
 * ([VehicleLost]), or when it disarms under a wait that needs it armed ([DisarmedDuring]).
 */
internal class StateWaits(private val vehicle: MavlinkVehicle, private val confirmTimeout: Duration) {
    /**
     * Waits for [ok] on [state]; fails on timeout with the last value seen (in words, by
     * [describe]), when the vehicle is lost, or, with [untilDisarmed], as soon as it disarms.
     */
    suspend fun <T> confirm(
        action: String,
        expected: String,
        state: Flow<T>,
        timeout: Duration = confirmTimeout,
        untilDisarmed: Boolean = false,
        describe: (T) -> String = ::stateText,
        ok: (T) -> Boolean,
    ) {
        var last: T? = null
        var seen = false
        val outcome = withTimeoutOrNull(timeout) {
            combine(state, vehicle.connection, vehicle.telemetry.armed) { value, connection, armed -> Triple(value, connection, armed) }
                .first { (value, connection, armed) ->
                    last = value
                    seen = true
                    ok(value) || connection == ConnectionState.LOST || (untilDisarmed && !armed)
                }
        } ?: run {
            // The state can turn right at the deadline, after the check saw it but before `first`
            // returned: what was seen last decides, not the race.
            @Suppress("UNCHECKED_CAST")
            if (seen && ok(last as T)) return
            throw ActionNotConfirmed(action, expected, if (seen) describe(last as T) else "nothing", timeout)
        }
        if (ok(outcome.first)) return
        if (outcome.second == ConnectionState.LOST) throw VehicleLost(vehicle.systemId, action)
        throw DisarmedDuring(vehicle.systemId, action, describe(outcome.first))
    }

    /** Waits until the heartbeat shows the mode that plays [role]. */
    suspend fun confirmMode(action: String, role: ModeRole) {
        val name = vehicle.modeFor(role)
        confirm(action, "mode $name", vehicle.telemetry.mode) { it?.name == name }
    }

    /** Throws [VehicleDisarmed] unless the vehicle reports its motors armed: nothing is sent for [action] then. */
    fun requireArmed(action: String) {
        if (!vehicle.telemetry.armed.value) throw VehicleDisarmed(vehicle.systemId, action)
    }

    /** Whether the vehicle shows, within a few telemetry reports, that it has left the ground. */
    suspend fun leavingGround(): Boolean = withTimeoutOrNull(LEAVING_GROUND_WAIT) {
        combine(vehicle.telemetry.landedState, vehicle.telemetry.position) { landed, position ->
            isAirborne(landed, position?.relativeAltitude)
        }.first { it }
    } ?: false

    private companion object {
        /** A few telemetry reports: long enough for a climbing vehicle's landed state or height to show it. */
        val LEAVING_GROUND_WAIT = 3.seconds
    }
}
