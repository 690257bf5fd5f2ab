package pod.core.units

import kotlin.math.roundToLong
import kotlin.time.Duration

/**
 * [this] as a person reads it in a message, rounded to what matters at its size: "0.4 s",
 * "10.0 s", "1 min 30 s", "2 h 5 min"; "forever" for an infinite duration. Never the
 * nanoseconds of [Duration.toString] ("10.001305558s").
 */
public fun Duration.toReadable(): String {
    if (isInfinite()) return if (isPositive()) "forever" else "-forever"
    if (isNegative()) return "-" + (-this).toReadable()
    val tenths = (inWholeMilliseconds / 100.0).roundToLong()
    if (tenths < 600) return "${tenths / 10}.${tenths % 10} s"
    val seconds = (inWholeMilliseconds / 1000.0).roundToLong()
    if (seconds < 3600) return "${seconds / 60} min" + (if (seconds % 60 != 0L) " ${seconds % 60} s" else "")
    val minutes = (seconds / 60.0).roundToLong()
    return "${minutes / 60} h" + (if (minutes % 60 != 0L) " ${minutes % 60} min" else "")
}
