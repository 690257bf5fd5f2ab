package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldMatch
import io.kotest.matchers.string.shouldNotContain
import io.kotest.matchers.string.shouldStartWith
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withTimeout
import pod.cli.Output
import pod.cli.json.Event
import pod.core.POD_VERSION
import java.io.File
import java.net.DatagramSocket
import java.net.InetAddress
import java.nio.file.Files
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import pod.cli.run as runPod

/** What one `pod` run printed and how it ended. */
internal class Ran(val code: Int, val out: List<String>, val err: List<String>) {
    val text: String get() = (out + err).joinToString("\n")

    /** With `--json`: the lines after the first, which must be Pod's version ([Event.PodVersion]). */
    val afterVersion: List<String> get() {
        withClue(text) { decodeEvent(out.first()) shouldBe Event.PodVersion(POD_VERSION) }
        return out.drop(1)
    }
}

/**
 * Runs `pod` in-process through its real entry point ([runPod], what `main` calls), waiting at
 * most [within]: a command that checks its input before the network returns long before that,
 * where one that opened the link would wait the minute its `--wait` asks for.
 */
internal suspend fun pod(vararg args: String, within: Duration = 20.seconds): Ran {
    val out = CopyOnWriteArrayList<String>()
    val err = CopyOnWriteArrayList<String>()
    val code = withTimeout(within) {
        runInterruptible(Dispatchers.IO) { runPod(args.toList(), Output { out += it }, Output { err += it }, debug = false) }
    }
    return Ran(code, out, err)
}

/** A file in [dir] holding [text]. */
private fun File.file(name: String, text: String): String = resolve(name).also { it.writeText(text) }.path

/**
 * The acceptance test of issue 12: every subcommand met with bad arguments and bad files ends with
 * the documented exit code (2: bad usage or input) and one line naming what is wrong, never a stack
 * trace, and before any link is opened: the vehicle commands are pointed at a free port with
 * `--wait 60s`, so one that reached the network would outlast [pod]'s 20 s.
 */
class BadInputSpec : StringSpec({
    val dir = Files.createTempDirectory("pod-bad-input").toFile()
    afterSpec { dir.deleteRecursively() }

    val wpl = "QGC WPL 110\n"
    val item = "0\t0\t3\t16\t0\t0\t0\t0\t41.1\t-8.6\t30\t1\n"
    val valid = dir.file("valid.waypoints", wpl + item)
    val headerOnly = dir.file("empty.waypoints", wpl)
    val malformed = dir.file("malformed.waypoints", wpl + item + "1\t0\t3\t16\t0\t0\t0\t0\tnorth\t-8.6\t30\t1\n")
    val binary = dir.resolve("binary.waypoints").also { f -> f.writeBytes(ByteArray(256) { (it * 7 + 0x80).toByte() }) }.path
    // One more than a MISSION_COUNT can announce: the reader must refuse it, not the upload.
    val oversized = dir.resolve("oversized.waypoints").also { f ->
        f.bufferedWriter().use { w -> w.write(wpl); repeat(65_536) { w.write(item) } }
    }.path
    val script = dir.file("plan.waypoints.main.kts", "println(1)\n")
    val noDir = dir.resolve("no-such-dir").resolve("out.waypoints").path
    val garbageTlog = dir.resolve("garbage.tlog").also { f -> f.writeBytes(ByteArray(64) { (it * 13 + 1).toByte() }) }.path
    val badGeoJson = dir.file("bad.geojson", "{\"type\": \"FeatureCollection\", \"features\": [{\"type\": \"Feature\"}]}")
    val svgOut = dir.resolve("map.svg").path

    // Where a vehicle command would look for a vehicle if it got that far: nobody is there.
    fun link(): Array<String> = arrayOf("--connect", "udpin:127.0.0.1:${freePort()}", "--wait", "60s")

    /** [args] and the text the one error line must contain, naming the bad input. */
    data class Case(val args: List<String>, val names: String)

    fun case(names: String, vararg args: String) = Case(args.toList(), names)

    val cases = listOf(
        case("--frob", "--frob"),
        case("fly", "fly"),
        case("--vehicles", "sim", "--vehicles", "0"),
        case("fast", "sim", "--speedup", "fast"),
        case("fast", "sim", "--time-scale", "fast"),
        case("nowhere", "sim", "--out", "nowhere"),
        case("254", "sim", "--sysid", "254", "--vehicles", "2"),
        case("65535", "sim", "--vehicles", "3", "--out", "udpin:127.0.0.1:65534"),
        case("10parsecs", "watch", "--duration", "10parsecs"),
        case("-1s", "watch", "--lost-after", "-1s"),
        case("udp-in:x:1", "watch", "--connect", "udp-in:x:1"),
        case("--vehicles", "demo", "--vehicles", "1"),
        case("forever", "demo", "--for", "forever"),
        case("no-such-dir", "demo", "--map", dir.resolve("no-such-dir").resolve("map.svg").path),
        case("SCRIPT", "run"),
        case("missing.main.kts", "run", "missing.main.kts"),
        case("valid.waypoints", "run", valid),
        case("--sim", "run", script, "--sim", "0"),
        case("--sim", "run", script, "--sim", "2", "--connect", "udpin:127.0.0.1:14550"),
        case("udpin:127.0.0.1", "run", script, "--connect", "udpin:127.0.0.1"),
        case("FILE", "mission", "upload", *link()),
        case("no-such.waypoints", "mission", "upload", dir.resolve("no-such.waypoints").path, *link()),
        case("binary.waypoints", "mission", "upload", binary, *link()),
        case("65535", "mission", "upload", oversized, *link()),
        case("line 3", "mission", "upload", malformed, *link()),
        case("--allow-empty", "mission", "upload", headerOnly, *link()),
        case("is a directory", "mission", "upload", dir.path, *link()),
        case("nofence", "mission", "upload", valid, "--type", "nofence", *link()),
        case("not a fence command", "mission", "upload", valid, "--type", "fence", *link()),
        case("no-such-dir", "mission", "download", noDir, *link()),
        case("is a directory", "mission", "download", dir.path, *link()),
        case("nowhere:1", "mission", "clear", "--connect", "nowhere:1"),
        case("0s", "mission", "clear", "--connect", "udpin:127.0.0.1:${freePort()}", "--wait", "0s"),
        case("--sysid", "mission", "clear", "--sysid", "0", *link()),
        case("THIS_NAME_IS_WAY_TOO_LONG_FOR_MAVLINK", "param", "get", "THIS_NAME_IS_WAY_TOO_LONG_FOR_MAVLINK", *link()),
        case("NAME", "param", "get", *link()),
        case("VALUE", "param", "set", "COM_DISARM_PRFLT", *link()),
        case("abc", "param", "set", "COM_DISARM_PRFLT", "abc", *link()),
        case("NaN", "param", "set", "COM_DISARM_PRFLT", "NaN", *link()),
        case("--frob", "param", "set", "COM_DISARM_PRFLT", "-1", "--frob", *link()),
        case("--frob", "arm", "--frob", *link()),
        case("300", "arm", "--sysid", "300", *link()),
        case("extra", "disarm", "extra", *link()),
        case("NAME", "mode", *link()),
        case("-5", "takeoff", "-5", *link()),
        case("abc", "takeoff", "abc", *link()),
        case("was 0", "takeoff", "0", *link()),
        case("ALT", "takeoff", *link()),
        case("--frob", "land", "--frob", *link()),
        case("soon", "rtl", "--wait", "soon", "--connect", "udpin:127.0.0.1:${freePort()}"),
        case("91", "goto", "91", "0", "10", *link()),
        case("ALT", "goto", "41.1", "-8.6", *link()),
        case("--frob", "goto", "41.1", "-8.6", "10", "--frob", *link()),
        case("tcp:host:0", "pause", "--connect", "tcp:host:0"),
        case("99999", "resume", "--connect", "udpin:127.0.0.1:99999"),
        case("-1", "start", "--from", "-1", *link()),
        case("x", "start", "--from", "x", *link()),
        case("10.0.0.1:14660", "queue", "serve", "--control", "10.0.0.1:14660", *link()),
        case("-3", "queue", "serve", "--takeoff", "-3", *link()),
        case("--radius", "queue", "append", "circle", "--north", "0", "--east", "0"),
        case("was 0", "queue", "append", "circle", "--north", "0", "--east", "0", "--radius", "0"),
        case("1,2,3", "queue", "prepend", "segment", "--from", "1,2,3", "--to", "0,0"),
        case("abc", "queue", "replace", "goto", "--north", "abc", "--east", "0"),
        case("a path needs at least one point", "queue", "replace-all", "path"),
        case("--frob", "queue", "next", "--frob"),
        case("extra", "queue", "clear", "extra"),
        case("99999", "queue", "status", "--control", "127.0.0.1:99999"),
        case("INPUT", "map", "--out", svgOut),
        case("--out", "map", valid),
        case("map.png", "map", valid, "--out", dir.resolve("map.png").path),
        case("no-such.tlog", "map", dir.resolve("no-such.tlog").path, "--out", svgOut),
        case("garbage.tlog", "map", garbageTlog, "--out", svgOut),
        case("feature 0", "map", badGeoJson, "--out", svgOut),
        case("notes.md", "map", "notes.md", "--out", svgOut),
        case("no-such-dir", "map", valid, "--out", dir.resolve("no-such-dir").resolve("map.svg").path),
        case("map.png", "demo", "--map", dir.resolve("map.png").path),
        case("FILE", "replay"),
        case("no-such.tlog", "replay", dir.resolve("no-such.tlog").path),
        case("garbage.tlog", "replay", garbageTlog),
        case("empty.tlog", "replay", dir.file("empty.tlog", "")),
        case("is a directory", "replay", dir.path),
        case("--speed", "replay", garbageTlog, "--speed", "0"),
        case("fast", "replay", garbageTlog, "--speed", "fast"),
        case("map.png", "replay", garbageTlog, "--map", dir.resolve("map.png").path),
        case("forever", "replay", garbageTlog, "--lost-after", "forever"),
    )

    "every subcommand meets bad arguments and bad files with exit 2 and one line naming the input, before the network" {
        // `pod --help` lists every subcommand; each is exercised above.
        val listed = pod("--help").out.joinToString("\n")
        for (name in listOf("sim", "watch", "replay", "demo", "map", "run", "mission", "param", "arm", "disarm", "mode", "takeoff", "land", "rtl", "goto", "pause", "resume", "start", "queue")) {
            withClue("pod --help lists $name") { listed shouldContain name }
            withClue("a bad-input case runs $name") { cases.any { it.args.firstOrNull() == name } shouldBe true }
        }
        for (sub in listOf(listOf("mission", "upload"), listOf("mission", "download"), listOf("mission", "clear"), listOf("param", "get"), listOf("param", "set"),
            listOf("queue", "serve"), listOf("queue", "append"), listOf("queue", "prepend"), listOf("queue", "replace"), listOf("queue", "replace-all"),
            listOf("queue", "next"), listOf("queue", "clear"), listOf("queue", "status"),
        )) {
            withClue("a bad-input case runs pod ${sub.joinToString(" ")}") { cases.any { it.args.take(2) == sub } shouldBe true }
        }
        for (c in cases) {
            val ran = pod(*c.args.toTypedArray())
            withClue("pod ${c.args.joinToString(" ")} printed:\n${ran.text}") {
                ran.code shouldBe 2
                ran.text shouldNotContain "Exception in thread"
                ran.text shouldNotContain "\tat "
                ran.text shouldNotContain "at pod."
                ran.err shouldHaveSize 1
                ran.err.single() shouldStartWith "error: "
                ran.err.single() shouldContain c.names
            }
        }
    }

    "a port in use is exit 2 for every command that opens a link, pod run --connect included" {
        DatagramSocket(0, InetAddress.getByName("127.0.0.1")).use { taken ->
            val address = "udpin:127.0.0.1:${taken.localPort}"
            for (args in listOf(listOf("watch", "--connect", address), listOf("arm", "--connect", address), listOf("run", script, "--connect", address), listOf("queue", "serve", "--connect", address, "--control", "127.0.0.1:0"))) {
                val ran = pod(*args.toTypedArray())
                withClue("pod ${args.joinToString(" ")} printed:\n${ran.text}") {
                    ran.code shouldBe 2
                    ran.err.single() shouldContain "already in use"
                }
            }
        }
    }

    "negative numbers are values where they make sense: the command gets as far as looking for the vehicle" {
        for (args in listOf(listOf("param", "set", "COM_DISARM_PRFLT", "-1"), listOf("goto", "41.1", "-8.6", "10"), listOf("goto", "-33.9", "151.2", "10"))) {
            val ran = pod(*args.toTypedArray(), "--connect", "udpin:127.0.0.1:${freePort()}", "--wait", "1s")
            withClue("pod ${args.joinToString(" ")} printed:\n${ran.text}") {
                // Exit 1, the vehicle's part: the number was taken; no "no such option -1".
                ran.code shouldBe 1
                ran.err.single() shouldContain "vehicle"
                ran.err.single() shouldNotContain "option"
            }
        }
    }

    "--help shows every option's default" {
        val help = pod("mission", "upload", "--help")
        help.code shouldBe 0
        val text = help.out.joinToString("\n")
        text shouldContain "udpin:0.0.0.0:14550"
        text shouldContain "10s"
        text shouldContain "(default: mission)" // the choice a person types, not the enum's name
        pod("sim", "--help").out.joinToString("\n") shouldContain "udpout:127.0.0.1:14550"
        // Where -5 is a number, -h still asks for help.
        for (command in listOf("takeoff", "goto", "param set")) {
            val h = pod(*command.split(" ").toTypedArray(), "-h")
            withClue("pod $command -h printed:\n${h.text}") {
                h.code shouldBe 0
                h.out.joinToString("\n") shouldContain "Usage: pod $command"
            }
        }
    }

    "with --json a bad input is also an error event on stdout, the only line there after Pod's version" {
        val ran = pod("param", "set", "THIS_NAME_IS_WAY_TOO_LONG_FOR_MAVLINK", "1", "--json", *link())
        ran.code shouldBe 2
        ran.err shouldHaveSize 1
        val event = decodeEvent(ran.afterVersion.single()).shouldBeInstanceOf<Event.Error>()
        event.message shouldContain "THIS_NAME_IS_WAY_TOO_LONG_FOR_MAVLINK"
        ran.err.single() shouldBe "error: ${event.message}"
    }

    "pod --version says Pod's version, the one every --json run starts with" {
        val ran = pod("--version")
        ran.code shouldBe 0
        ran.out shouldBe listOf("pod $POD_VERSION")
        POD_VERSION shouldMatch Regex("""0\.\d+\.\d+""")
    }

    "a tlog with no record at all is bad input, exit 2, whether it is to be mapped or played" {
        val empty = dir.resolve("nothing.tlog").also { it.writeBytes(ByteArray(0)) }.path
        for (args in listOf(listOf("map", empty, "--out", svgOut), listOf("replay", empty))) {
            val ran = pod(*args.toTypedArray())
            withClue(ran.text) {
                ran.code shouldBe 2
                ran.err.single() shouldBe "error: $empty is empty: no tlog record to ${if (args[0] == "map") "map" else "play"}"
            }
        }
    }

    "a duration is one format in every option: a bare number is seconds, and units are welcome" {
        val ran = pod("watch", "--connect", "udpin:127.0.0.1:0", "--duration", "1", "--lost-after", "2", "--json")
        withClue(ran.text) { ran.code shouldBe 0 }
    }

    "an unexpected failure is one line and exit 1, not a stack trace" {
        val err = CopyOnWriteArrayList<String>()
        // An output that breaks is a failure no command foresees.
        val code = withTimeout(20.seconds) {
            runInterruptible(Dispatchers.IO) {
                runPod(
                    listOf("watch", "--connect", "udpin:127.0.0.1:0", "--duration", "1s", "--json"),
                    Output { throw IllegalStateException("the terminal went away") },
                    Output { err += it },
                    debug = false,
                )
            }
        }
        code shouldBe 1
        err shouldHaveSize 1
        err.single() shouldContain "the terminal went away"
        err.single() shouldContain "internal error"
        err.single() shouldContain "POD_DEBUG=1"
    }

    "the pod process itself: a too-long parameter name is one line on stderr and exit 2, no 'Exception in thread'" {
        val java = File(System.getProperty("java.home"), "bin/java").path
        val process = ProcessBuilder(
            java, "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "pod.cli.MainKt",
            "param", "get", "THIS_NAME_IS_WAY_TOO_LONG_FOR_MAVLINK", "--connect", "udpin:127.0.0.1:${freePort()}", "--wait", "60s",
        ).start()
        process.outputStream.close()
        val code = withTimeout(30.seconds) { runInterruptible(Dispatchers.IO) { process.waitFor() } }
        val err = process.errorStream.bufferedReader().readLines()
        val out = process.inputStream.bufferedReader().readText()
        code shouldBe 2
        out shouldBe ""
        err shouldHaveSize 1
        err.single() shouldContain "THIS_NAME_IS_WAY_TOO_LONG_FOR_MAVLINK"
        err.single() shouldNotContain "Exception"
    }
})
