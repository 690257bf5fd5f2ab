package pod.mavlink.radio

/**
 * How a [pod.mavlink.GroundStation] paces what it sends once a telemetry radio reports
 * RADIO_STATUS, so that the radio's transmit buffer never overflows: a SiK radio drops the serial
 * bytes that find its buffer full (serial.c, `serial_interrupt`: `serial_rx_overflow++`), which
 * cuts frames in half and costs retries at best.
 *
 * Pacing is a token bucket of [burst] bytes refilled at a rate that starts at [initialRate] and
 * follows each report's `txbuf` (free buffer, percent), in the four bands ArduPilot uses to slow
 * its own streams (libraries/GCS_MAVLink/GCS_Common.cpp, `GCS_MAVLINK::handle_radio_status`:
 * below 20 % slow down a lot, below 50 % a little, above 90 % speed up a little, above 95 % more):
 * below [criticalBelow] % the rate halves, below [lowBelow] % it drops by a quarter, above
 * [roomyAbove] % it grows by [increase] bytes/s, above [emptyAbove] % by twice that, always within
 * [minRate]..[maxRate]. Multiplicative decrease and additive increase, as TCP's congestion control:
 * a report comes only about once a second (on our own HEARTBEAT), so the rate must fall fast when
 * the buffer fills and creep up while it stays empty, or the next second overflows it.
 *
 * MAVProxy (1.8.75, checked in its sources) shows the radio's rssi and noise but does not pace on
 * `txbuf`; a mission upload is paced by the vehicle's requests anyway. What overflows a radio is
 * what a ground station sends unasked and back to back: a parameter file pushed with PARAM_SET,
 * stream requests for a fleet, commands from a loop, an upload's catch-up burst after a loss.
 *
 * The defaults suit a 57600-baud SiK pair: [initialRate] is half of the 5760 bytes/s its serial
 * line carries (10 bits a byte), so the first second after the first report cannot fill a
 * 2048-byte buffer; [maxRate] is a 115200-baud line's.
 */
public data class RadioPacing(
    /** Whether to pace at all; reports are parsed into [pod.mavlink.GroundStation.radio] either way. */
    public val enabled: Boolean = true,
    /** Bytes per second allowed once the first report is heard. */
    public val initialRate: Int = 2_880,
    /** The rate never falls below this (bytes/s): a buffer reported full still drains. */
    public val minRate: Int = 240,
    /** The rate never grows past this (bytes/s). */
    public val maxRate: Int = 11_520,
    /** Bytes that may leave back to back after a quiet spell. */
    public val burst: Int = 512,
    /** Bytes/s added per report above [roomyAbove] % free (twice that above [emptyAbove] %). */
    public val increase: Int = 240,
    /** Free percent below which the rate halves. */
    public val criticalBelow: Int = 20,
    /** Free percent below which the rate drops by a quarter. */
    public val lowBelow: Int = 50,
    /** Free percent above which the rate grows by [increase]. */
    public val roomyAbove: Int = 90,
    /** Free percent above which the rate grows by twice [increase]. */
    public val emptyAbove: Int = 95,
) {
    init {
        require(minRate >= 1) { "minRate must be ≥ 1 byte/s, was $minRate" }
        require(maxRate >= minRate) { "maxRate must be ≥ minRate ($minRate), was $maxRate" }
        require(initialRate in minRate..maxRate) { "initialRate must be in $minRate..$maxRate bytes/s, was $initialRate" }
        require(burst >= 1) { "burst must be ≥ 1 byte, was $burst" }
        require(increase >= 0) { "increase must be ≥ 0, was $increase" }
        require(criticalBelow in 0..lowBelow && lowBelow <= roomyAbove && roomyAbove <= emptyAbove && emptyAbove <= 100) {
            "thresholds must satisfy 0 ≤ criticalBelow ≤ lowBelow ≤ roomyAbove ≤ emptyAbove ≤ 100, were $criticalBelow, $lowBelow, $roomyAbove, $emptyAbove"
        }
    }

    /** Pacing switched off. */
    public companion object {
        /** No pacing: reports are still parsed and shown, sends are never delayed. */
        public val Off: RadioPacing = RadioPacing(enabled = false)
    }
}
