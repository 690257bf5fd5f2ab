package pod.mavlink.mission

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldEndWith
import io.kotest.matchers.string.shouldStartWith
import io.kotest.property.Arb
import io.kotest.property.RandomSource
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.float
import io.kotest.property.checkAll
import java.nio.file.Files
import kotlin.random.Random

private val otherFrames = listOf(MissionItem.FRAME_MISSION, 22, 255)
private val allFrames = (MissionItem.GLOBAL_FRAMES + MissionItem.LOCAL_FRAMES + otherFrames).toList()

/** Floats where a text format breaks first: NaN, signed zero, subnormals, extremes, non-terminating binaries. */
private val specialFloats = listOf(
    Float.NaN, 0f, -0f, 0.1f, 12.3f, -1f, 1e-7f, Float.MIN_VALUE, Float.MAX_VALUE, -Float.MAX_VALUE,
    Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, 123456.79f, 1.5e20f,
)

/** An integer from [range], with its ends and zero over-represented (they are where off-by-ones live). */
private fun Random.edgy(range: IntRange): Int = when (nextInt(6)) {
    0 -> range.first
    1 -> range.last
    2 -> 0.coerceIn(range)
    else -> nextInt(range.first, range.last) + nextInt(2)
}

private fun Random.param(floats: Arb<Float>, rs: RandomSource): Float =
    if (nextInt(3) == 0) specialFloats.random(this) else floats.sample(rs).value

/** Random lists of one mission type, seq = index, over global, local, mission and unknown frames. */
private val itemLists: Arb<List<MissionItem>> = arbitrary { rs ->
    val r = rs.random
    val floats = Arb.float()
    val type = MissionType.entries.random(r)
    List(r.nextInt(0, 30)) { seq ->
        val frame = allFrames.random(r)
        val global = frame in MissionItem.GLOBAL_FRAMES
        MissionItem(
            seq = seq, frame = frame, command = r.edgy(0..65_535),
            current = r.nextBoolean(), autocontinue = r.nextBoolean(),
            param1 = r.param(floats, rs), param2 = r.param(floats, rs),
            param3 = r.param(floats, rs), param4 = r.param(floats, rs),
            x = if (global) r.edgy(-900_000_000..900_000_000) else r.edgy(Int.MIN_VALUE..Int.MAX_VALUE),
            y = if (global) r.edgy(-1_800_000_000..1_800_000_000) else r.edgy(Int.MIN_VALUE..Int.MAX_VALUE),
            z = r.param(floats, rs), missionType = type,
        )
    }
}

private const val LINE = "0\t0\t3\t16\t0\t0\t0\t0\t41.1234567\t-8.5432101\t30\t1"

/** The failure of reading a file whose data line (line 2) is [line]. */
private fun failureOf(line: String): WplFormatException =
    shouldThrow<WplFormatException> { WplFile.read("QGC WPL 110\n$line\n") }

internal class WplFileTest : FunSpec({

    test("random lists of every type and frame survive write then read unchanged") {
        checkAll(1_000, itemLists) { items ->
            val text = WplFile.write(items)
            withClue(text) { WplFile.read(text, items.firstOrNull()?.missionType ?: MissionType.MISSION) shouldBe items }
        }
    }

    test("a 7-decimal coordinate and the ±90/±180 extremes survive exactly") {
        val items = listOf(
            MissionItem(0, 3, 16, x = 411_234_567, y = -85_432_101, z = 30f),
            MissionItem(1, 0, 16, x = -900_000_000, y = 1_800_000_000),
            MissionItem(2, 10, 16, x = 900_000_000, y = -1_800_000_000),
            MissionItem(3, 0, 16, x = -1, y = 5),
        )
        val text = WplFile.write(items)
        text shouldContain "41.1234567\t-8.5432101\t30\t"
        text shouldContain "-90.0000000\t180.0000000\t"
        text shouldContain "-0.0000001\t0.0000005\t"
        WplFile.read(text) shouldBe items
    }

    test("the writer emits the header, tab-separated columns, readable floats and LF line ends") {
        val items = listOf(
            MissionItem(0, 3, 22, current = true, param1 = 15f, param4 = Float.NaN, x = 411_234_567, y = -85_432_101, z = 12.3f),
            MissionItem(1, 1, 16, autocontinue = false, param2 = 0.1f, x = 12_345, y = -5, z = -0f),
            MissionItem(2, MissionItem.FRAME_MISSION, 177, param1 = 1f, param2 = 3f, x = 7, y = -2),
        )
        WplFile.write(items) shouldBe
            "QGC WPL 110\n" +
            "0\t1\t3\t22\t15\t0\t0\tnan\t41.1234567\t-8.5432101\t12.3\t1\n" +
            "1\t0\t1\t16\t0\t0.1\t0\t0\t1.2345\t-0.0005\t-0\t0\n" +
            "2\t0\t2\t177\t1\t3\t0\t0\t7\t-2\t0\t1\n"
    }

    test("floats are written in the shortest form that reads back as the same Float") {
        WplFile.formatFloat(0.1f) shouldBe "0.1"
        WplFile.formatFloat(100f) shouldBe "100"
        WplFile.formatFloat(-2.5f) shouldBe "-2.5"
        WplFile.formatFloat(1e-10f) shouldBe "1E-10"
        WplFile.formatFloat(Float.MAX_VALUE) shouldBe "3.4028235E+38"
        WplFile.formatFloat(Float.NEGATIVE_INFINITY) shouldBe "-inf"
    }

    test("comments, blank lines, CRLF, a BOM, runs of spaces, nan/NaN and QGC's 120 header are accepted") {
        val text = "\uFEFF# saved by hand\r\n\r\nQGC WPL 120\r\n# takeoff\r\n" +
            "0  1   3 22 0 0 0 NaN 41.1234567 -8.5432101 30 1\r\n" +
            "   \r\n  # indented comment\r\n" +
            "1\t0\t3\t16\tnan\t+2.5\t.5\t-INF\t41.12345675\t-8.54321015\t1.5e2\t1"
        WplFile.read(text, MissionType.RALLY) shouldBe listOf(
            MissionItem(
                0, 3, 22, current = true, param4 = Float.NaN, x = 411_234_567, y = -85_432_101, z = 30f,
                missionType = MissionType.RALLY,
            ),
            // Half-way coordinates round to nearest, ties away from zero.
            MissionItem(
                1, 3, 16, param1 = Float.NaN, param2 = 2.5f, param3 = 0.5f, param4 = Float.NEGATIVE_INFINITY,
                x = 411_234_568, y = -85_432_102, z = 150f, missionType = MissionType.RALLY,
            ),
        )
    }

    test("reads pymavlink's %f output, rounding 6-decimal degrees to the wire integer") {
        val text = "QGC WPL 110\n0\t0\t3\t16\t0.000000\t0.000000\t0.000000\tnan\t-35.363262\t149.165237\t584.000000\t1\n" +
            "1\t0\t2\t178\t1.000000\t15.000000\t-1.000000\t0.000000\t3.000000\t-4.000000\t0.000000\t1\n"
        WplFile.read(text) shouldBe listOf(
            MissionItem(0, 3, 16, param4 = Float.NaN, x = -353_632_620, y = 1_491_652_370, z = 584f),
            MissionItem(1, 2, 178, param1 = 1f, param2 = 15f, param3 = -1f, x = 3, y = -4),
        )
    }

    test("items are renumbered by position unless renumber = false, which rejects a gap") {
        val text = "QGC WPL 110\n5\t0\t3\t16\t0\t0\t0\t0\t1\t2\t3\t1\n0\t0\t3\t16\t0\t0\t0\t0\t1\t2\t3\t1\n"
        WplFile.read(text).map { it.seq } shouldBe listOf(0, 1)
        val e = shouldThrow<WplFormatException> { WplFile.read(text, renumber = false) }
        e.lineNumber shouldBe 2
        e.message shouldBe "WPL line 2: seq 5 where 0 was expected (numbering must run 0, 1, 2, …)"
    }

    test("a missing or foreign header fails on the line where the header should be") {
        shouldThrow<WplFormatException> { WplFile.read("# only a comment\n\n") }.message shouldBe
            "WPL line 1: no 'QGC WPL 110' header: the text holds only blank or comment lines"
        shouldThrow<WplFormatException> { WplFile.read("# x\nQGC WPL 100\n") }.message shouldBe
            "WPL line 2: expected the header 'QGC WPL 110', found 'QGC WPL 100'"
        shouldThrow<WplFormatException> { WplFile.read("# x\n$LINE\n") }.message shouldBe
            "WPL line 2: expected the header 'QGC WPL 110', found '$LINE'"
    }

    test("each kind of bad line fails with its line number and reason") {
        fun line(vararg replace: Pair<Int, String>): String =
            LINE.split('\t').toMutableList().apply { replace.forEach { (i, v) -> set(i, v) } }.joinToString("\t")
        val cases = mapOf(
            LINE.substringBeforeLast('\t') to
                "expected 12 columns (seq current frame command param1 param2 param3 param4 x y z autocontinue), found 11",
            "$LINE\t7" to "expected 12 columns (seq current frame command param1 param2 param3 param4 x y z autocontinue), found 13",
            line(3 to "16.0") to "command '16.0' is not an integer",
            line(5 to "abc") to "param2 'abc' is not a number",
            line(10 to "1f") to "z '1f' is not a number",
            line(7 to "1e39") to "param4 1e39 is outside the Float range",
            line(0 to "65536") to "seq 65536 is outside 0..65535",
            line(2 to "256") to "frame 256 is outside 0..255",
            line(2 to "-1") to "frame -1 is outside 0..255",
            line(3 to "70000") to "command 70000 is outside 0..65535",
            line(1 to "2") to "current 2 must be 0 or 1",
            line(11 to "-1") to "autocontinue -1 must be 0 or 1",
            line(8 to "90.00000006") to "latitude 90.00000006 is outside ±90°",
            line(8 to "-91") to "latitude -91 is outside ±90°",
            line(9 to "180.5") to "longitude 180.5 is outside ±180°",
            line(9 to "-1e999999999") to "longitude -1e999999999 is outside ±180°",
            line(8 to "nan") to "latitude nan is not a finite number; MISSION_ITEM_INT carries it as an integer",
            line(9 to "east") to "longitude 'east' is not a number",
            line(2 to "1", 8 to "214748.3648") to "x 214748.3648 m is beyond the ±214748.3647 m MISSION_ITEM_INT carries",
            line(2 to "2", 8 to "4.000000", 9 to "1.5") to "y 1.5 must be a whole number in frame 2 (x/y are plain integers there)",
            line(2 to "2", 8 to "3e9") to "x 3e9 is outside the Int range",
        )
        for ((bad, reason) in cases) {
            withClue(bad) {
                val e = failureOf(bad)
                e.lineNumber shouldBe 2
                e.reason shouldBe reason
                e.message shouldBe "WPL line 2: $reason"
            }
        }
    }

    test("the reader and the upload check agree: 65535 items fit a MISSION_COUNT, 65536 are refused by the reader") {
        val most = buildString {
            append("QGC WPL 110\n")
            repeat(MissionValidation.MAX_ITEMS) { append("0\t0\t3\t16\t0\t0\t0\t0\t41.1\t-8.6\t30\t1\n") }
        }
        val items = WplFile.read(most)
        items.size shouldBe 65_535
        MissionValidation.check(MissionType.MISSION, items) // what an upload would check first: no throw
        val e = shouldThrow<WplFormatException> { WplFile.read(most + "0\t0\t3\t16\t0\t0\t0\t0\t41.1\t-8.6\t30\t1\n") }
        e.lineNumber shouldBe 65_537
        e.reason shouldBe "a list holds at most 65535 items"
        shouldThrow<InvalidMission> { MissionValidation.check(MissionType.MISSION, items + items.last().copy(seq = 65_535)) }.message shouldBe
            "invalid mission item 65535: at most 65535 items fit a MISSION_COUNT, the list has 65536"
    }

    test("a binary first line is shown short and readable in the header error") {
        val e = shouldThrow<WplFormatException> { WplFile.read("\u0001ELF\u0002" + "x".repeat(100) + "\n") }
        e.reason shouldBe "expected the header 'QGC WPL 110', found '?ELF?${"x".repeat(55)}…'"
    }

    test("the line number counts comments and blank lines") {
        val e = shouldThrow<WplFormatException> {
            WplFile.read("# a\r\nQGC WPL 110\r\n\r\n$LINE\r\n# b\r\n${LINE.replace("\t3\t16\t", "\t3\tx\t")}\r\n")
        }
        e.lineNumber shouldBe 6
        e.message shouldBe "WPL line 6: command 'x' is not an integer"
    }

    test("the writer refuses what could not be read back") {
        shouldThrow<IllegalArgumentException> { WplFile.write(listOf(MissionItem(1, 3, 16))) }.message shouldBe
            "items[0].seq must be 0, was 1"
        shouldThrow<IllegalArgumentException> { WplFile.write(listOf(MissionItem(0, 3, 16, x = 900_000_001))) }.message shouldBe
            "items[0] latitude 90.0000001 is outside ±90°"
        shouldThrow<IllegalArgumentException> { WplFile.write(listOf(MissionItem(0, 0, 16, y = -1_800_000_001))) }.message shouldBe
            "items[0] longitude -180.0000001 is outside ±180°"
    }

    test("path overloads write UTF-8 and read it back") {
        val file = Files.createTempFile("pod-wpl", ".waypoints")
        try {
            val items = listOf(MissionItem(0, 5, 5000, x = 1, y = 2, missionType = MissionType.FENCE))
            WplFile.write(file, items)
            Files.readString(file) shouldStartWith "QGC WPL 110\n"
            Files.readString(file) shouldEndWith "\t1\n"
            WplFile.read(file, MissionType.FENCE) shouldBe items
        } finally {
            Files.deleteIfExists(file)
        }
    }
})
