package pod.mavlink.signing

/**
 * The signing timestamp: 10 µs units since 2015-01-01 00:00:00 UTC (the MAVLink signing
 * specification), never going backwards and growing by at least one per frame signed, so that
 * frames signed within the same 10 µs still carry increasing timestamps.
 */
public class SigningClock(private val epochMillis: () -> Long) {
    private var last = 0L

    /** The timestamp for the next frame signed. */
    @Synchronized
    public fun next(): Long {
        val wall = fromEpochMillis(epochMillis())
        last = maxOf(wall, last + 1)
        return last
    }

    /**
     * Raises the clock to [timestamp], a verified frame's: the next frame signed carries a later
     * one. The MAVLink C library does this in `mavlink_signature_check` ("our next timestamp must
     * be at least this timestamp") and pymavlink in `check_signature`, so a peer whose clock runs
     * ahead never sees our frames as a stream more than a minute old.
     */
    @Synchronized
    public fun observe(timestamp: Long) {
        if (timestamp > last) last = timestamp
    }

    /** The current signing time without using a timestamp (for [ReplayGuard.accept]'s `now`). */
    @Synchronized
    public fun now(): Long = maxOf(fromEpochMillis(epochMillis()), last)

    /** Converts between Unix time and MAVLink signing timestamps. */
    public companion object {
        /** 2015-01-01 00:00:00 UTC in milliseconds since the Unix epoch. */
        public const val EPOCH_2015_MILLIS: Long = 1_420_070_400_000

        /** [millis] since the Unix epoch as a signing timestamp (10 µs units since 2015). */
        public fun fromEpochMillis(millis: Long): Long = (millis - EPOCH_2015_MILLIS) * 100
    }
}
