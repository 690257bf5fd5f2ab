package pod.e2e.artifacts

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.string.shouldContain
import pod.e2e.shrunk.describe
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MessageCodec
import java.io.File
import java.nio.file.Files
import java.util.concurrent.CompletableFuture
import java.util.concurrent.TimeUnit
import java.util.zip.ZipFile

/**
 * pod-mavlink's R8/ProGuard consumer rules (META-INF/proguard/pod-mavlink.pro in its jar) are what
 * lets an app that shrinks still decode MAVLink: the app in pod.e2e.shrunk, shrunk by R8 with the
 * jar's rules, decodes a HEARTBEAT and a GLOBAL_POSITION_INT into io.dronefleet messages exactly as
 * unshrunk; shrunk without them, it does not.
 *
 * Two R8 runs over pod-mavlink, pod-core and io.dronefleet (~1,400 classes each time), side by side.
 */
class ShrunkDecoderSpec : StringSpec({
    val work = Files.createTempDirectory("pod-r8").toFile()
    afterSpec { work.deleteRecursively() }
    val r8 = R8Shrink(work)
    val main = "pod.e2e.shrunk.DecoderAppKt"
    val appClasses = File(Class.forName(main).protectionDomain.codeSource.location.toURI()).resolve("pod/e2e/shrunk")
        .listFiles { f -> f.name.endsWith(".class") }!!.toList()

    val heartbeat = Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
        .customMode(4).systemStatus(MavState.MAV_STATE_ACTIVE).mavlinkVersion(3).build()
    val position = GlobalPositionInt.builder().timeBootMs(123_456).lat(-353_632_621).lon(1_491_652_374).alt(584_000)
        .relativeAlt(20_000).vx(150).vy(-20).vz(5).hdg(27_000).build()
    val frames = listOf(heartbeat, position).mapIndexed { i, m -> FrameEncoder().encode(m, systemId = 1, componentId = 1, sequence = i) }
    val hex = frames.map { bytes -> bytes.joinToString("") { "%02x".format(it) } }

    /** What the unshrunk app prints: the same describe() on this JVM's own decode. */
    val expected = buildList {
        val decoder = FrameDecoder()
        frames.forEach { bytes -> decoder.feed(bytes) { add(describe(it.messageId, MessageCodec.Default.decode(it))) } }
    }

    /** Runs the shrunk [jar]'s main on the frames: exit code and printed lines. */
    fun run(jar: File): Pair<Int, List<String>> {
        val out = File(work, "${jar.nameWithoutExtension}.out")
        val process = ProcessBuilder(listOf(R8Shrink.javaCommand(), "-cp", jar.path + File.pathSeparator + r8.stdlib.path, main) + hex)
            .redirectErrorStream(true).redirectOutput(out).start()
        // A bound against a hung child, not a timing assertion.
        check(process.waitFor(2, TimeUnit.MINUTES)) { process.destroyForcibly(); "the shrunk app did not finish" }
        return process.exitValue() to out.readLines()
    }

    /**
     * Both R8 runs, started together when the first is wanted: R8 spends much of a run on one
     * thread, so on two cores the pair takes little longer than one.
     */
    val shrinks = lazy {
        val bare = r8.without(r8.mavlink, "META-INF/proguard/", "pod-mavlink-without-rules.jar")
        listOf("with-rules" to r8.mavlink, "without-rules" to bare).associate { (name, jar) ->
            name to CompletableFuture.supplyAsync { r8.shrink(name, appClasses, main, mavlinkJar = jar) }
        }
    }

    "the unshrunk app decodes both frames into io.dronefleet messages" {
        expected shouldBe listOf(
            "HEARTBEAT type=MAV_TYPE_QUADROTOR autopilot=MAV_AUTOPILOT_ARDUPILOTMEGA customMode=4 status=MAV_STATE_ACTIVE version=3",
            "GLOBAL_POSITION_INT time=123456 lat=-353632621 lon=1491652374 alt=584000 relativeAlt=20000 vx=150 hdg=27000",
        )
    }

    "pod-mavlink's jar carries its consumer rules under META-INF/proguard" {
        ZipFile(r8.mavlink).use { zip -> zip.getEntry("META-INF/proguard/pod-mavlink.pro") shouldNotBe null }
    }

    "shrunk by R8 with the rules R8 finds in pod-mavlink's jar, the app decodes as unshrunk" {
        val shrunk = shrinks.value.getValue("with-rules").get()
        withClue(shrunk.log) { shrunk.exitCode shouldBe 0 }
        // The rules came from the jar: the app's own configuration names only its main class.
        shrunk.configuration.readText() shouldContain "@io.dronefleet.mavlink.annotations.MavlinkMessageInfo"
        val (exit, lines) = run(shrunk.output)
        withClue(lines.joinToString("\n")) {
            exit shouldBe 0
            lines shouldBe expected
        }
    }

    "shrunk without the rules, the same app no longer decodes: the rules are needed" {
        val shrunk = shrinks.value.getValue("without-rules").get()
        withClue(shrunk.log) { shrunk.exitCode shouldBe 0 }
        val (exit, lines) = run(shrunk.output)
        withClue(lines.joinToString("\n")) {
            (exit != 0 || lines != expected) shouldBe true
            lines.none { it.startsWith("HEARTBEAT type=") } shouldBe true
        }
    }
})
