package pod.mavlink.action

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import pod.core.vehicle.GpsFix
import pod.mavlink.MavStates
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.CommandRejected
import pod.mavlink.protocol.RetryPolicy
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * Waiting out a vehicle that is still initialising: a command it refuses with a reason that clears
 * by waiting (the estimator has no origin yet, no GPS fix, sensors settling: [ArmReadiness]) is
 * sent again every second, ArduPilot's pre-arm check rate, for up to [readyTimeout] in all, with
 * [waitingFor] saying why; then [VehicleNotReady]. Other refusals are thrown as they are.
 */
internal class Readiness(private val vehicle: MavlinkVehicle, private val readyTimeout: Duration) {
    private val _waitingFor = MutableStateFlow<String?>(null)

    /** What a retried command is waiting for now, in the autopilot's words, or null. */
    val waitingFor: StateFlow<String?> = _waitingFor.asStateFlow()

    /**
     * Runs [attempt] for [action] ("arm", "switch to GUIDED") until it is not refused with a
     * reason [waitFor] names (null: one waiting will not clear), or [readyTimeout] from now is over.
     */
    suspend fun retry(action: String, waitFor: (CommandRejected) -> String?, attempt: suspend () -> Unit) {
        val started = vehicle.clock.markNow()
        val policy = RetryPolicy(
            RETRY_PAUSE, readyTimeout, RetryPolicy.LastPause.WHOLE,
            retried = { e -> (e as? CommandRejected)?.let(waitFor) },
            giveUp = { _, reason -> VehicleNotReady(vehicle.systemId, reason, readyTimeout, action) },
        )
        try {
            policy.run(vehicle.clock, started, onWait = { _waitingFor.value = it }, attempt = attempt)
        } finally {
            _waitingFor.value = null
        }
    }

    /** What the vehicle's own reports say about it still booting: no home, no 3D fix, or a booting heartbeat. */
    fun initialising(): Boolean {
        val t = vehicle.telemetry
        return t.home.value == null || (t.gps.value?.fix?.let { it < GpsFix.FIX_3D } ?: false) ||
            MavStates.isStartingUp(t.systemStatus.value)
    }

    private companion object {
        /** Between attempts while the vehicle initialises: ArduPilot runs its pre-arm checks at 1 Hz. */
        val RETRY_PAUSE = 1.seconds
    }
}
