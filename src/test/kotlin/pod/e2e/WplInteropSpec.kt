package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.doubles.shouldBeLessThanOrEqual
import io.kotest.matchers.ints.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.WplFile
import java.math.BigDecimal
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit
import kotlin.io.path.deleteRecursively
import kotlin.math.abs
import kotlin.math.roundToInt
import kotlin.random.Random

/** One item as pymavlink's mavwp holds it: x/y/params/z are Python floats (degrees in global frames). */
private class PyItem(val fields: List<String>) {
    fun int(i: Int): Int = fields[i].toInt()
    fun double(i: Int): Double = when (fields[i]) {
        "nan" -> Double.NaN
        "inf" -> Double.POSITIVE_INFINITY
        "-inf" -> Double.NEGATIVE_INFINITY
        else -> fields[i].toDouble()
    }

    /** As a Pod item: floats narrowed the way MAVLink packs them, coordinates rounded to the wire integer. */
    fun toMissionItem(): MissionItem {
        val frame = int(2)
        val scale = when (frame) {
            in MissionItem.GLOBAL_FRAMES -> 1e7
            in MissionItem.LOCAL_FRAMES -> 1e4
            else -> 1.0
        }
        return MissionItem(
            seq = int(0), frame = frame, command = int(3), current = int(1) == 1, autocontinue = int(11) == 1,
            param1 = double(4).toFloat(), param2 = double(5).toFloat(),
            param3 = double(6).toFloat(), param4 = double(7).toFloat(),
            x = (double(8) * scale).roundToInt(), y = (double(9) * scale).roundToInt(), z = double(10).toFloat(),
            missionType = MissionType.of(int(12))!!,
        )
    }
}

/** Runs wpl_peer.py with [args], at most 60 s, and returns what it printed. */
private fun peer(dir: Path, vararg args: String): List<String> {
    val out = dir.resolve("peer-${System.nanoTime()}.out").toFile()
    val process = ProcessBuilder(listOf(Python.executable, Python.script("wpl_peer.py")) + args)
        .redirectOutput(out)
        .redirectError(ProcessBuilder.Redirect.INHERIT)
        .start()
    if (!process.waitFor(60, TimeUnit.SECONDS)) {
        process.destroyForcibly()
        error("wpl_peer.py ${args.toList()} did not finish within 60 s")
    }
    check(process.exitValue() == 0) { "wpl_peer.py ${args.toList()} exited with ${process.exitValue()}" }
    return out.readLines().filter { it.isNotBlank() }
}

private fun <T> withTempDir(block: (Path) -> T): T {
    val dir = Files.createTempDirectory("pod-wpl-interop")
    try {
        return block(dir)
    } finally {
        @OptIn(kotlin.io.path.ExperimentalPathApi::class)
        dir.deleteRecursively()
    }
}

private val frames = (MissionItem.GLOBAL_FRAMES + MissionItem.LOCAL_FRAMES + listOf(MissionItem.FRAME_MISSION, 30)).toList()

/** [count] random items of [type], with edge values mixed in; params come from [param]. */
private fun randomItems(type: MissionType, count: Int, random: Random, param: Random.() -> Float): List<MissionItem> =
    List(count) { seq ->
        val frame = frames.random(random)
        val global = frame in MissionItem.GLOBAL_FRAMES
        fun coordinate(limit: Int): Int = when (random.nextInt(5)) {
            0 -> limit
            1 -> -limit
            else -> random.nextInt(-limit, limit)
        }
        MissionItem(
            seq = seq, frame = frame,
            // Not 0 first: mavwp turns a command-0 first item into NAV_WAYPOINT (Mission Planner's home).
            command = random.nextInt(1, 65_536), current = random.nextBoolean(), autocontinue = random.nextBoolean(),
            param1 = random.param(), param2 = random.param(), param3 = random.param(), param4 = random.param(),
            x = coordinate(if (global) 900_000_000 else 2_000_000_000),
            y = coordinate(if (global) 1_800_000_000 else 2_000_000_000),
            z = random.param(), missionType = type,
        )
    }

private val anyFloats = listOf(Float.NaN, 0f, -0f, 0.1f, 12.3f, 1e-7f, 3.4028235e38f, Float.MIN_VALUE, Float.NEGATIVE_INFINITY)

/** Any Float, often an awkward one: Pod writes each so that it survives exactly. */
private fun Random.anyFloat(): Float = if (nextInt(3) == 0) anyFloats.random(this) else Float.fromBits(nextInt()).let {
    if (it.isNaN()) 1.5f else it
}

/** A Float whose value pymavlink's %f (6 decimals) keeps: up to 3 decimals, NaN, or -0. */
private fun Random.sixDecimalFloat(): Float = when (nextInt(8)) {
    0 -> Float.NaN
    1 -> -0f
    else -> BigDecimal.valueOf(nextLong(-100_000_000, 100_000_000), 3).toFloat()
}

class WplInteropSpec : StringSpec({

    "pymavlink's mavwp loads what Pod writes: coordinates within 1e-7°, params and z exactly" {
        withTempDir { dir ->
            val random = Random(20261115)
            for (type in MissionType.entries) {
                val items = listOf(
                    MissionItem(
                        0, 3, 22, current = true, param4 = Float.NaN, x = 411_234_567, y = -85_432_101, z = 30f, missionType = type,
                    ),
                    MissionItem(1, 0, 16, param1 = 0.1f, x = -900_000_000, y = 1_800_000_000, z = -0f, missionType = type),
                    MissionItem(2, 1, 16, x = -1, y = 12_345, missionType = type),
                    MissionItem(
                        3, MissionItem.FRAME_MISSION, 178, autocontinue = false, x = Int.MIN_VALUE, y = Int.MAX_VALUE,
                        missionType = type,
                    ),
                ) + randomItems(type, 200, random) { anyFloat() }.map { it.copy(seq = it.seq + 4) }
                val file = dir.resolve("pod-${type.name.lowercase()}.waypoints")
                WplFile.write(file, items)

                val loaded = peer(dir, "load", file.toString(), type.name.lowercase()).map { PyItem(it.split('\t')) }
                loaded shouldHaveSize items.size
                loaded.zip(items).forEach { (py, item) ->
                    withClue("$type item ${item.seq}: ${py.fields}") {
                        if (item.isGlobal) {
                            abs(py.double(8) - item.latitude) shouldBeLessThanOrEqual 1e-7
                            abs(py.double(9) - item.longitude) shouldBeLessThanOrEqual 1e-7
                        }
                        py.toMissionItem() shouldBe item
                    }
                }
            }
        }
    }

    "Pod reads what pymavlink's mavwp saves: coordinates within its 6 decimals, all else exactly" {
        withTempDir { dir ->
            val random = Random(7)
            for (type in MissionType.entries) {
                val items = randomItems(type, 200, random) { sixDecimalFloat() }
                val itemsFile = dir.resolve("items-${type.name.lowercase()}.tsv")
                Files.writeString(itemsFile, items.joinToString("") { toPeerLine(it) })
                val file = dir.resolve("mavwp-${type.name.lowercase()}.waypoints")
                peer(dir, "save", itemsFile.toString(), file.toString(), type.name.lowercase())

                val read = WplFile.read(file, type)
                read shouldHaveSize items.size
                read.zip(items).forEach { (pod, item) ->
                    withClue("$type item ${item.seq}") {
                        if (item.isGlobal) {
                            // %f keeps 6 decimals: at most 0.5e-6° = 5 wire units off.
                            abs(pod.x - item.x) shouldBeLessThanOrEqual 5
                            abs(pod.y - item.y) shouldBeLessThanOrEqual 5
                            pod.copy(x = item.x, y = item.y) shouldBe item
                        } else {
                            pod shouldBe item
                        }
                    }
                }
            }
        }
    }

    "mavwp turns a command-0 first item into NAV_WAYPOINT; Pod keeps the file's command" {
        withTempDir { dir ->
            val items = listOf(MissionItem(0, 0, 0, x = 1, y = 2), MissionItem(1, 0, 0, x = 3, y = 4))
            val file = dir.resolve("home.waypoints")
            WplFile.write(file, items)
            peer(dir, "load", file.toString(), "mission").map { it.split('\t')[3].toInt() } shouldBe listOf(16, 0)
            WplFile.read(file) shouldBe items
        }
    }
})

/** [item] in wpl_peer.py's ITEMS layout, coordinates in the units mavwp keeps (degrees, metres). */
private fun toPeerLine(item: MissionItem): String {
    val decimals = when (item.frame) {
        in MissionItem.GLOBAL_FRAMES -> 7
        in MissionItem.LOCAL_FRAMES -> 4
        else -> 0
    }
    fun coordinate(v: Int) = BigDecimal.valueOf(v.toLong(), decimals).toPlainString()
    return listOf(
        item.seq, if (item.current) 1 else 0, item.frame, item.command,
        item.param1, item.param2, item.param3, item.param4, coordinate(item.x), coordinate(item.y), item.z,
        if (item.autocontinue) 1 else 0, item.missionType.mavValue,
    ).joinToString("\t", postfix = "\n")
}
