package pod.mavlink.mission

import java.math.BigDecimal
import java.math.BigInteger
import java.math.MathContext
import java.math.RoundingMode
import java.nio.file.Files
import java.nio.file.Path

/**
 * A line of a QGC WPL file that cannot be read: [lineNumber] counts from 1 over every line of the text
 * (blank and comment lines included), and [reason] says what is wrong with it.
 */
public class WplFormatException(
    /** The 1-based line of the text that failed. */
    public val lineNumber: Int,
    /** Why the line was rejected, naming the column and the allowed range. */
    public val reason: String,
) : pod.core.PodException("WPL line $lineNumber: $reason")

/**
 * Reads and writes mission, fence and rally lists as QGC WPL 110 text, the format of Mission Planner,
 * MAVProxy and pymavlink's `mavwp`.
 *
 * Each item is one line of twelve tab-separated columns,
 * `seq current frame command param1 param2 param3 param4 x y z autocontinue`. x/y hold decimal degrees in
 * global frames (written with 7 decimals, the full MISSION_ITEM_INT precision, where mavwp writes 6),
 * metres in local frames and plain integers otherwise. The file does not say which list it holds: the
 * caller names the [MissionType] when reading. ArduPilot's convention of home at seq 0 is not interpreted:
 * items come back exactly as the file lists them.
 */
public object WplFile {
    /** The header line this object writes. */
    public const val HEADER: String = "QGC WPL 110"

    // QGC 3.x wrote "QGC WPL 120" with the same twelve columns (its files just lack a home item).
    private val acceptedHeaders = setOf(listOf("QGC", "WPL", "110"), listOf("QGC", "WPL", "120"))
    private val columnNames = listOf(
        "seq", "current", "frame", "command", "param1", "param2", "param3", "param4", "x", "y", "z", "autocontinue",
    )

    // Plain and scientific decimals, which both Kotlin and Python's float() read (nan/inf go through
    // [special]); Java's hex floats and 1f/1d suffixes, and Python's 1_000, are refused.
    private val decimal = Regex("[+-]?(\\d+(\\.\\d*)?|\\.\\d+)([eE][+-]?\\d+)?")
    private val whitespace = Regex("\\s+")
    // What one MISSION_COUNT can announce: a longer file could be read but never uploaded.
    private const val MAX_ITEMS = MissionValidation.MAX_ITEMS

    /**
     * The WPL text of [items]: the header, then one `\n`-terminated line per item.
     *
     * Params and z are written in the shortest decimal that reads back as the same Float (`nan`, `inf`
     * and `-inf` for the special values, which Python's `float()` also reads).
     *
     * @throws IllegalArgumentException when an item's seq is not its index in [items], or a global item's
     *   latitude/longitude is outside ±90°/±180° (such a file could not be read back).
     */
    public fun write(items: List<MissionItem>): String = buildString {
        append(HEADER).append('\n')
        items.forEachIndexed { index, item ->
            require(item.seq == index) { "items[$index].seq must be $index, was ${item.seq}" }
            if (item.isGlobal) {
                require(item.x in -LAT_LIMIT..LAT_LIMIT) { "items[$index] latitude ${degrees(item.x)} is outside ±90°" }
                require(item.y in -LON_LIMIT..LON_LIMIT) { "items[$index] longitude ${degrees(item.y)} is outside ±180°" }
            }
            val columns = listOf(
                index.toString(), bit(item.current), item.frame.toString(), item.command.toString(),
                formatFloat(item.param1), formatFloat(item.param2), formatFloat(item.param3), formatFloat(item.param4),
                coordinate(item.frame, item.x), coordinate(item.frame, item.y), formatFloat(item.z), bit(item.autocontinue),
            )
            columns.joinTo(this, "\t")
            append('\n')
        }
    }

    /** Writes [items] to [path] as UTF-8 WPL text (see [write]), replacing the file. */
    public fun write(path: Path, items: List<MissionItem>) {
        Files.writeString(path, write(items))
    }

    /**
     * The items of WPL [text], all tagged with [missionType].
     *
     * The header must be the first line that is neither blank nor a `#` comment; blank and comment lines
     * may appear anywhere. Columns may be separated by tabs or runs of spaces; lines may end in CRLF.
     * Coordinates are rounded to the nearest wire integer (degrees × 10⁷, metres × 10⁴).
     *
     * Numbering: with [renumber] (the default, as mavwp does) items get seq 0, 1, 2, … in file order and
     * the seq column only has to be an integer in 0..65535, so a hand-edited file with a deleted line still
     * loads. With `renumber = false` the seq column must already read 0, 1, 2, …, and a gap or repeat fails.
     *
     * @throws WplFormatException naming the first bad line and why it is bad.
     */
    public fun read(text: String, missionType: MissionType = MissionType.MISSION, renumber: Boolean = true): List<MissionItem> {
        val items = mutableListOf<MissionItem>()
        var headerSeen = false
        text.removePrefix("\uFEFF").lines().forEachIndexed { index, line ->
            val content = line.trim()
            if (content.isEmpty() || content.startsWith("#")) return@forEachIndexed
            val lineNumber = index + 1
            val fields = content.split(whitespace)
            if (!headerSeen) {
                if (fields !in acceptedHeaders) {
                    throw WplFormatException(lineNumber, "expected the header '$HEADER', found '${shown(content)}'")
                }
                headerSeen = true
            } else {
                if (items.size == MAX_ITEMS) throw WplFormatException(lineNumber, "a list holds at most $MAX_ITEMS items")
                items += ItemLine(lineNumber, fields).parse(items.size, missionType, renumber)
            }
        }
        if (!headerSeen) throw WplFormatException(1, "no '$HEADER' header: the text holds only blank or comment lines")
        return items
    }

    /** Reads the UTF-8 WPL file at [path]; see [read] for the rules and errors. */
    public fun read(path: Path, missionType: MissionType = MissionType.MISSION, renumber: Boolean = true): List<MissionItem> =
        read(Files.readString(path), missionType, renumber)

    /** One data line being parsed; every failure names [lineNumber]. */
    private class ItemLine(val lineNumber: Int, val fields: List<String>) {
        fun parse(position: Int, missionType: MissionType, renumber: Boolean): MissionItem {
            if (fields.size != columnNames.size) {
                fail("expected ${columnNames.size} columns (${columnNames.joinToString(" ")}), found ${fields.size}")
            }
            val seq = integer(0, 0, 65_535)
            if (!renumber && seq != position) fail("seq $seq where $position was expected (numbering must run 0, 1, 2, …)")
            val frame = integer(2, 0, 255)
            return MissionItem(
                seq = position,
                frame = frame,
                command = integer(3, 0, 65_535),
                current = integer(1, 0, 1) == 1,
                autocontinue = integer(11, 0, 1) == 1,
                param1 = float(4),
                param2 = float(5),
                param3 = float(6),
                param4 = float(7),
                x = coordinate(8, frame),
                y = coordinate(9, frame),
                z = float(10),
                missionType = missionType,
            )
        }

        fun fail(reason: String): Nothing = throw WplFormatException(lineNumber, reason)

        fun integer(column: Int, min: Int, max: Int): Int {
            val name = columnNames[column]
            val value = fields[column].toBigIntegerOrNull() ?: fail("$name '${fields[column]}' is not an integer")
            if (value < BigInteger.valueOf(min.toLong()) || value > BigInteger.valueOf(max.toLong())) {
                fail(if (max - min == 1) "$name $value must be $min or $max" else "$name $value is outside $min..$max")
            }
            return value.toInt()
        }

        fun float(column: Int): Float {
            val token = fields[column]
            special(token)?.let { return it }
            if (!decimal.matches(token)) fail("${columnNames[column]} '$token' is not a number")
            val value = token.toFloat()
            if (value.isInfinite()) fail("${columnNames[column]} $token is outside the Float range")
            return value
        }

        /** [column] (x or y) as the MISSION_ITEM_INT integer for [frame]. */
        fun coordinate(column: Int, frame: Int): Int {
            val token = fields[column]
            val global = frame in MissionItem.GLOBAL_FRAMES
            val name = if (global) (if (column == 8) "latitude" else "longitude") else columnNames[column]
            val allInts = Int.MIN_VALUE..Int.MAX_VALUE
            val (decimals, range, outside) = when {
                global && column == 8 -> Triple(7, -LAT_LIMIT..LAT_LIMIT, "is outside ±90°")
                global -> Triple(7, -LON_LIMIT..LON_LIMIT, "is outside ±180°")
                frame in MissionItem.LOCAL_FRAMES ->
                    Triple(4, allInts, "m is beyond the ±214748.3647 m MISSION_ITEM_INT carries")
                else -> Triple(0, allInts, "is outside the Int range")
            }
            if (special(token) != null) fail("$name $token is not a finite number; MISSION_ITEM_INT carries it as an integer")
            if (!decimal.matches(token)) fail("$name '$token' is not a number")
            // BigDecimal rejects exponents beyond the Int range: such a value is out of range here anyway.
            val value = try {
                BigDecimal(token)
            } catch (_: NumberFormatException) {
                fail("$name $token $outside")
            }
            val units = wire(value, decimals, range) ?: fail("$name $token $outside")
            if (decimals == 0 && value.compareTo(BigDecimal.valueOf(units.toLong())) != 0) {
                fail("$name $token must be a whole number in frame $frame (x/y are plain integers there)")
            }
            return units
        }
    }

    /** [value] × 10^[decimals] rounded to nearest (ties away from zero), or null outside [range]. */
    private fun wire(value: BigDecimal, decimals: Int, range: IntRange): Int? {
        // Scaling 1e999999999 or 1e-999999999 would overflow or crawl; both are settled by magnitude alone.
        val integerDigits = value.precision().toLong() - value.scale()
        if (integerDigits > 12) return null
        if (integerDigits < -12) return 0
        val units = value.movePointRight(decimals)
        if (units <= BigDecimal.valueOf(range.first.toLong()).subtract(HALF)) return null
        if (units >= BigDecimal.valueOf(range.last.toLong()).add(HALF)) return null
        return units.setScale(0, RoundingMode.HALF_UP).intValueExact()
    }

    // A binary or foreign file's first line can be long and full of control characters: show a readable start.
    private fun shown(line: String): String {
        val printable = line.map { if (it.isISOControl() && it != '\t') '?' else it }.joinToString("")
        return if (printable.length > 60) printable.take(60) + "…" else printable
    }

    /** NaN or ±infinity in the spellings Python's float() accepts, or null for anything else. */
    private fun special(token: String): Float? {
        val negative = token.startsWith("-")
        return when (token.removePrefix("-").removePrefix("+").lowercase()) {
            "nan" -> Float.NaN
            "inf", "infinity" -> if (negative) Float.NEGATIVE_INFINITY else Float.POSITIVE_INFINITY
            else -> null
        }
    }

    private fun coordinate(frame: Int, value: Int): String = when (frame) {
        in MissionItem.GLOBAL_FRAMES -> degrees(value)
        in MissionItem.LOCAL_FRAMES -> BigDecimal.valueOf(value.toLong(), 4).toPlainString()
        else -> value.toString()
    }

    // Exact decimal arithmetic: going through Double could print 41.123456699999996.
    private fun degrees(value: Int): String = BigDecimal.valueOf(value.toLong(), 7).toPlainString()

    private fun bit(flag: Boolean): String = if (flag) "1" else "0"

    /**
     * The shortest decimal that reads back as [value], both directly as a Float (Pod) and via a Double
     * narrowed to Float (pymavlink's float() followed by MAVLink's float32 packing).
     */
    internal fun formatFloat(value: Float): String = when {
        value.isNaN() -> "nan"
        value == Float.POSITIVE_INFINITY -> "inf"
        value == Float.NEGATIVE_INFINITY -> "-inf"
        value == 0f -> if (1f / value < 0f) "-0" else "0" // BigDecimal would drop the sign of -0
        else -> {
            val exact = BigDecimal(value.toDouble())
            (1..17).asSequence()
                .map { digits -> plain(exact.round(MathContext(digits, RoundingMode.HALF_EVEN)).stripTrailingZeros()) }
                .first { it.toFloat() == value && it.toDouble().toFloat() == value }
        }
    }

    // Plain notation for everyday magnitudes, scientific (1.5E+20, which Python reads too) for the rest.
    private fun plain(value: BigDecimal): String {
        val exponent = value.precision() - value.scale() - 1
        return if (exponent in -7..12) value.toPlainString() else value.toString()
    }

    private const val LAT_LIMIT = 900_000_000
    private const val LON_LIMIT = 1_800_000_000
    private val HALF = BigDecimal("0.5")
}
