package pod.mavlink.mission

import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * Timeouts and retry budget of a mission transfer.
 *
 * The timeout adapts to the measured round trip (smoothed round trip plus four deviations, as TCP
 * does), between [minTimeout] and [maxTimeout]; it starts at [initialTimeout] and doubles after
 * each timeout without progress, up to 8× and [maxTimeout]. A transfer fails after [retries] timeouts in a
 * row and [patience] without progress. Download keeps up to [window] requests in flight.
 */
public data class TransferTiming(
    /** Timeout before any round trip was measured. */
    public val initialTimeout: Duration = 500.milliseconds,
    /**
     * Shortest timeout, whatever the measured round trip. It binds only on fast links (loopback,
     * Ethernet to a companion computer: a round trip through Pod's lossy relay is 0.3 ms median and
     * 4 ms p99); radio links' measured round trip sets a longer one. Chosen by measurement: at 30 %
     * loss on loopback, 10 ms moved missions 1.7–1.9× faster than 20 ms (BENCHMARKS.md), and a
     * timeout that fires early costs a repeated message, which vehicles ignore.
     */
    public val minTimeout: Duration = 10.milliseconds,
    /** Longest timeout, after backing off. */
    public val maxTimeout: Duration = 2.seconds,
    /**
     * Timeouts in a row without progress before the transfer fails. Generous on purpose: at 30 %
     * loss each way about half the retry rounds fail, and a dead link is noticed sooner from the
     * vehicle's heartbeat.
     */
    public val retries: Int = 20,
    /**
     * Least time without progress before a transfer fails, whatever [retries] says: a vehicle may
     * be ahead of us and waiting for its own re-request timer (ArduPilot's is 1 s), and at 30 %
     * loss several of those can go missing in a row.
     */
    public val patience: Duration = 10.seconds,
    /** Download requests kept in flight at most. */
    public val window: Int = 16,
    /**
     * How long after a vehicle appeared an upload refused with MAV_MISSION_NO_SPACE is tried
     * again: ArduPilot refuses every upload so while its mission storage is still starting, for
     * the first seconds after boot. Later, NO_SPACE means the list does not fit and fails at once.
     */
    public val serviceStartup: Duration = 30.seconds,
    /**
     * How long an upload or download the vehicle refuses with DENIED is tried again. ArduPilot
     * refuses every transfer but the upload it is receiving until that upload ends, and it ignores a
     * ground station's MISSION_ACK CANCELLED: an upload abandoned by this process or an earlier one
     * (an interrupted `pod mission upload`) is held until 8 s pass without an item
     * (MissionItemProtocol::handle_mission_request_list and handle_mission_count answer DENIED
     * while `receiving`; MissionItemProtocol::update times the upload out).
     */
    public val deniedRetry: Duration = 10.seconds,
) {
    init {
        require(minTimeout.isPositive()) { "minTimeout must be > 0, was $minTimeout" }
        require(maxTimeout >= minTimeout) { "maxTimeout must be ≥ minTimeout ($minTimeout), was $maxTimeout" }
        require(initialTimeout in minTimeout..maxTimeout) { "initialTimeout must be in $minTimeout..$maxTimeout, was $initialTimeout" }
        require(retries >= 1) { "retries must be ≥ 1, was $retries" }
        require(window in 1..256) { "window must be in 1..256, was $window" }
        require(!patience.isNegative()) { "patience must be ≥ 0, was $patience" }
        require(!serviceStartup.isNegative()) { "serviceStartup must be ≥ 0, was $serviceStartup" }
        require(!deniedRetry.isNegative()) { "deniedRetry must be ≥ 0, was $deniedRetry" }
    }
}

/**
 * Round-trip estimate and the timeout it implies; times are nanoseconds on the driver's clock.
 *
 * One estimator serves every transfer of a vehicle, so a transfer starts from what the previous
 * one measured instead of [TransferTiming.initialTimeout].
 */
internal class RoundTripEstimator(
    private val timing: TransferTiming,
    /** A floor the link sets now, in nanoseconds, above [TransferTiming.minTimeout] (a paced radio's; 0: none). */
    private val linkFloorNanos: () -> Long = { 0L },
) {
    private var smoothed = -1.0
    private var deviation = 0.0
    private var backoff = 1
    private var shortest = Long.MAX_VALUE

    /** Nanoseconds to wait for an answer now. */
    val timeoutNanos: Long
        get() {
            val base = if (smoothed < 0) timing.initialTimeout.inWholeNanoseconds.toDouble() else smoothed + 4 * deviation
            val floor = maxOf(timing.minTimeout.inWholeNanoseconds, linkFloorNanos()).coerceAtMost(timing.maxTimeout.inWholeNanoseconds)
            val clamped = base.coerceIn(floor.toDouble(), timing.maxTimeout.inWholeNanoseconds.toDouble())
            return (clamped * backoff).toLong().coerceAtMost(timing.maxTimeout.inWholeNanoseconds)
        }

    /**
     * A measured round trip (only of messages sent once: a retransmission's answer is ambiguous).
     *
     * [mayBeVehicleTimer]: the answer may have come from the vehicle's own re-request timer rather
     * than from what we sent (an upload's next request does, when the first one was lost). Such a
     * sample far above the shortest round trip seen is the vehicle's timer period (250 ms for PX4,
     * 1 s for ArduPilot), not the link: taking it would stretch our timeout past the vehicle's, after
     * which every one of its re-requests looks like a round trip and the estimate never comes down.
     */
    fun sample(nanos: Long, mayBeVehicleTimer: Boolean = false) {
        val r = nanos.coerceAtLeast(0)
        if (mayBeVehicleTimer && shortest != Long.MAX_VALUE && r > maxOf(8 * shortest, shortest + TIMER_MARGIN_NANOS)) return
        if (r < shortest) shortest = r
        if (smoothed < 0 || smoothed > 8.0 * r + TIMER_MARGIN_NANOS) {
            // First sample, or one showing that the estimate so far was inflated (by a vehicle timer
            // taken for a round trip before anything shorter was seen): start over from it.
            smoothed = r.toDouble()
            deviation = r / 2.0
        } else {
            deviation = 0.75 * deviation + 0.25 * kotlin.math.abs(smoothed - r)
            smoothed = 0.875 * smoothed + 0.125 * r
        }
        backoff = 1
    }

    /**
     * A timeout passed without an answer: wait twice as long next time, up to 8× (and
     * [TransferTiming.maxTimeout]). Capped low because on a lossy radio a late answer is a lost one
     * far more often than congestion, and every doubling is paid on each loss (unbounded doubling
     * made 1000-item PX4 downloads at 30 % loss take over 120 s); not capped at 2× because a
     * vehicle that stalls must not be hammered: MAVSDK's vehicle side drops a download after more
     * than 5 repeats of a request, which 10 ms timeouts doubling only once reached within 200 ms.
     */
    fun backOff() {
        if (backoff < MAX_BACKOFF) backoff *= 2
    }

    /** An answer arrived: stop backing off. */
    fun progressed() {
        backoff = 1
    }

    private companion object {
        const val TIMER_MARGIN_NANOS = 100_000_000L
        const val MAX_BACKOFF = 8
    }
}
