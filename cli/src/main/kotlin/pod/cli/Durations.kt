package pod.cli

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * Parses a duration the one way every `pod` option takes it: a bare number is seconds ("30",
 * "2.5"), anything else a duration with units ("30s", "2m", "500ms", "1m 30s", ISO-8601
 * "PT10S"); null unless positive and finite.
 */
internal fun String.toDurationOrNull(): Duration? {
    val text = trim()
    val parsed = text.toDoubleOrNull()?.takeIf { it.isFinite() }?.seconds ?: Duration.parseOrNull(text)
    return parsed?.takeIf { it.isPositive() && it.isFinite() }
}

/** The refusal of a duration option's value (format it with the value). */
internal const val NOT_A_DURATION = "'%s' is not a positive duration (30 or 30s is seconds; 2m, 500ms, 1m 30s)"

/** What every duration option's help says about its format. */
internal const val DURATION_FORMAT = "30 or 30s, 2m, 500ms"
