package pod.cli

/** One JSON object on one line, from ordered key/value pairs (strings, numbers, booleans, null). */
internal fun jsonLine(vararg pairs: Pair<String, Any?>): String = buildString {
    append('{')
    pairs.forEachIndexed { i, (key, value) ->
        if (i > 0) append(',')
        appendString(key)
        append(':')
        when (value) {
            null -> append("null")
            is Boolean, is Int, is Long -> append(value.toString())
            is Double -> if (value.isFinite()) append(value.toString()) else append("null")
            is Number -> append(value.toString())
            else -> appendString(value.toString())
        }
    }
    append('}')
}

private fun StringBuilder.appendString(s: String) {
    append('"')
    for (c in s) {
        when {
            c == '"' -> append("\\\"")
            c == '\\' -> append("\\\\")
            c == '\n' -> append("\\n")
            c < ' ' -> append("\\u").append(c.code.toString(16).padStart(4, '0'))
            else -> append(c)
        }
    }
    append('"')
}
