package pod.sim

import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.launch
import pod.mavlink.MessageIds
import pod.mavlink.command.CommandResult
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * What a simulated vehicle sends unasked: HEARTBEAT at 1 Hz and each telemetry stream at its
 * rate, starting from [defaults] (the firmware's own streams, or the configuration's) and changed
 * by a ground station's MAV_CMD_SET_MESSAGE_INTERVAL ([setInterval]). Each stream is a coroutine of
 * the scope given to [start], so it sends on the vehicle's clock; periods follow the vehicle's
 * simulated time ([sendPeriod]).
 */
internal class StreamScheduler(
    /** Message id → rate in Hz before anyone asks; also what an interval of 0 restores. */
    private val defaults: Map<Int, Double>,
    /** How many times real time the vehicle's clock runs. */
    private val timeScale: Double,
    /** The HEARTBEAT to send now. */
    private val heartbeat: () -> Any,
    /** The message [messageId] to send now, or null when there is nothing to say. */
    private val build: (messageId: Int) -> Any?,
    /** Whether the vehicle can send [messageId] at all. */
    private val canBuild: (messageId: Int) -> Boolean,
    private val send: suspend (message: Any) -> Unit,
) {
    private val _rates = MutableStateFlow(defaults)
    private val streams = HashMap<Int, Job>()
    private var scope: CoroutineScope? = null

    /** Message id → rate in Hz of what it streams now. */
    val rates: StateFlow<Map<Int, Double>> = _rates.asStateFlow()

    /** Starts the heartbeat and every stream at its current rate, as children of [scope]. */
    fun start(scope: CoroutineScope) {
        this.scope = scope
        scope.launch { every(sendPeriod(1.0)) { send(heartbeat()) } }
        for ((id, hz) in _rates.value) restart(scope, id, hz)
    }

    /** Forgets the streams of a stopped vehicle (cancelling its scope stopped them); rates stay as asked. */
    fun stop() {
        scope = null
        streams.clear()
    }

    /**
     * MAV_CMD_SET_MESSAGE_INTERVAL: [messageId] every [intervalUs] µs (-1 stops it, 0 restores its
     * default). HEARTBEAT and messages the vehicle cannot send are DENIED, and so is a rate above 1 kHz.
     */
    fun setInterval(messageId: Int, intervalUs: Float): CommandResult {
        if (messageId == MessageIds.HEARTBEAT || canBuild(messageId).not()) return CommandResult.DENIED
        val hz = when {
            intervalUs < 0 -> 0.0 // -1 disables the stream
            intervalUs == 0f -> defaults[messageId] ?: 1.0 // 0 restores the default
            else -> 1_000_000.0 / intervalUs
        }
        if (hz > 1000) return CommandResult.DENIED
        _rates.value = _rates.value + (messageId to hz)
        scope?.let { restart(it, messageId, hz) }
        return CommandResult.ACCEPTED
    }

    private fun restart(scope: CoroutineScope, messageId: Int, hz: Double) {
        streams.remove(messageId)?.cancel()
        if (hz <= 0) return
        streams[messageId] = scope.launch(CoroutineName("stream-$messageId")) {
            every(sendPeriod(hz)) { build(messageId)?.let { send(it) } }
        }
    }

    private fun sendPeriod(hz: Double): Duration = sendPeriod(hz, timeScale)

    private suspend inline fun every(period: Duration, action: () -> Unit): Nothing {
        while (true) {
            action()
            delay(period)
        }
    }

    companion object {
        /** With a time scale above 1, at most 50 sends a second per stream (see [sendPeriod]). */
        val MIN_SEND_PERIOD = 20.milliseconds

        /**
         * The wall-clock period of what a vehicle whose clock runs [timeScale] times real time sends
         * [hz] times per second of its own time. A simulated autopilot runs on its simulated clock,
         * as ArduPilot SITL does (AP_HAL::micros64() and millis64() return the scheduler's
         * stopped_clock_usec(), the simulation's time, so every scheduled send follows it:
         * libraries/AP_HAL_SITL/system.cpp): at time scale 40 a 1 Hz HEARTBEAT comes every 25 ms,
         * and a confirmation that waits for the next heartbeat costs a simulated second, not forty.
         * A vehicle slower than real time keeps real-time rates (a ground station must not take it
         * for lost), and no stream is sent more often than every [MIN_SEND_PERIOD] of wall time,
         * which bounds the datagrams a fast fleet sends.
         */
        fun sendPeriod(hz: Double, timeScale: Double): Duration {
            val real = (1.0 / hz).seconds
            if (timeScale <= 1.0) return real
            return (real / timeScale).coerceAtLeast(minOf(real, MIN_SEND_PERIOD))
        }
    }
}
