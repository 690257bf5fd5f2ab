package pod.bench

import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.jsonObject
import kotlin.math.roundToLong

/** The JSON the harnesses write (reports, the fleet server's lines) and read (peers' lines), as kotlinx.serialization trees. */
object JsonText {
    /** How reports are written: indented, for people and for bench/summarize.py. */
    val pretty: Json = Json { prettyPrint = true }

    /** [v] rounded to four decimals, or null when it is not finite (JSON has no NaN). */
    fun num(v: Double): JsonElement = if (v.isFinite()) JsonPrimitive((v * 1e4).roundToLong() / 1e4) else JsonNull

    /** [v] as [num], null staying null. */
    fun num(v: Double?): JsonElement = v?.let(::num) ?: JsonNull

    /**
     * The fields of a flat JSON object (one line a peer printed), each value as its text (strings
     * unquoted and unescaped, Python's NaN as "NaN"); null when the line is not a JSON object.
     */
    fun parseFlat(line: String): Map<String, String>? = try {
        Json.parseToJsonElement(line).jsonObject.mapValues { (_, v) -> if (v is JsonPrimitive) v.content else v.toString() }
    } catch (e: IllegalArgumentException) {
        null // not JSON (SerializationException), or not an object
    }
}
