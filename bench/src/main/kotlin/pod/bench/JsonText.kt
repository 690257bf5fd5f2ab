package pod.bench

import java.util.Locale

/** The little JSON the harnesses write by hand: escaped strings and finite numbers. */
object JsonText {
    /** [v] with four decimals, or null when it is not finite. */
    fun num(v: Double): String = if (v.isFinite()) String.format(Locale.ROOT, "%.4f", v) else "null"

    /** [s] as a JSON string literal. */
    fun str(s: String): String = buildString {
        append('"')
        for (c in s) when {
            c == '"' -> append("\\\"")
            c == '\\' -> append("\\\\")
            c < ' ' -> append(String.format(Locale.ROOT, "\\u%04x", c.code))
            else -> append(c)
        }
        append('"')
    }

    private val FIELD = Regex("""\"(\w+)\":\s*("(?:[^"\\]|\\.)*"|[^,}]+)""")

    /** The fields of a flat JSON object (one line a peer printed), values as strings, quotes removed. */
    fun parseFlat(line: String): Map<String, String> =
        FIELD.findAll(line).associate { m -> m.groupValues[1] to m.groupValues[2].trim().removeSurrounding("\"") }
}
