package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldEndWith
import io.kotest.matchers.string.shouldNotContain
import io.kotest.matchers.string.shouldStartWith
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.withContext
import pod.core.units.Location
import pod.sim.SimFleet
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.seconds
import java.io.File
import java.nio.file.Files
import java.util.concurrent.TimeUnit

/** What `pod run` printed and how it exited. */
private class Run(val exitCode: Int, val out: List<String>, val err: String) {
    /** [err] without the line that says a script is being compiled. */
    val errors: String get() = err.lines().filterNot { it.startsWith("pod: compiling ") }.joinToString("\n")
}

/**
 * `pod run` as a person runs it: a JVM of its own (`pod.cli.MainKt` on this test's classpath, as
 * the `./pod` launcher starts it), scripts from src/test/resources/scripts, a fresh script cache.
 */
class ScriptRunSpec : StringSpec({
    val cache = Files.createTempDirectory("pod-script-cache").toFile()
    afterSpec { cache.deleteRecursively() }

    fun script(name: String): String =
        File(ScriptRunSpec::class.java.getResource("/scripts/$name")!!.toURI()).path

    fun pod(vararg args: String): Run {
        val dir = Files.createTempDirectory("pod-run").toFile()
        try {
            val java = File(System.getProperty("java.home"), "bin/java").path
            val process = ProcessBuilder(
                listOf(java, "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "pod.cli.MainKt") +
                    args,
            ).redirectOutput(File(dir, "out")).redirectError(File(dir, "err")).redirectInput(ProcessBuilder.Redirect.PIPE)
                .also { it.environment()["POD_SCRIPT_CACHE"] = cache.path }
                .start()
            process.outputStream.close()
            // A bound against a hung child, not a timing assertion.
            check(process.waitFor(5, TimeUnit.MINUTES)) { process.destroyForcibly(); "pod run did not finish" }
            return Run(process.exitValue(), File(dir, "out").readLines(), File(dir, "err").readText())
        } finally {
            dir.deleteRecursively()
        }
    }

    val distance = "distance: %.3f m".format(Location(41.1785, -8.5957).distanceTo(Location(41.1795, -8.5957)).meters)

    "a script uses Pod's classes (core, dsl), sees the fleet pod run chose, and gets its arguments" {
        val run = pod("run", script("fleet-and-distance.main.kts"), "--sim", "3", "--time-scale", "10", "--", "alpha", "--beta")
        // A new script takes seconds to compile: pod run says so instead of sitting silent.
        run.err.trim() shouldBe "pod: compiling fleet-and-distance.main.kts (about 10 s for a new or changed script; later runs start at once)"
        run.exitCode shouldBe 0
        run.out shouldContainExactly listOf(distance, "fleet: Sim(count=3, timeScale=10.0)", "dsl: PodDsl", "args: alpha --beta")
    }

    "the same script again runs from the cache and gets the link and time scale given with --connect" {
        // pod run tries a udpin port before compiling (a port in use is exit 2): a free one here.
        val address = "udpin://127.0.0.1:${freePort()}"
        // --time-scale for a simulator run faster (pod sim --time-scale 10): durations count in its time.
        val run = pod("run", script("fleet-and-distance.main.kts"), "--connect", address, "--time-scale", "10")
        run.err shouldBe "" // nothing to compile
        run.exitCode shouldBe 0
        run.out shouldContainExactly listOf(distance, "fleet: Connect(address=$address, timeScale=10.0, keyFile=null)", "dsl: PodDsl", "args: ")
        cache.listFiles()!!.filter { it.name.endsWith(".jar") } shouldHaveSize 1
    }

    "a syntax error is reported at its file and line, with exit code 2 (bad input) and no stack trace" {
        val run = pod("run", script("syntax-error.main.kts"))
        run.exitCode shouldBe 2
        run.out shouldBe emptyList()
        run.err shouldContain "syntax-error.main.kts:4:"
        run.err shouldContain "error:"
        run.err shouldNotContain "Exception"
        run.err shouldNotContain "\tat "
    }

    "an exception thrown by the script prints its message and the script's line, with exit code 1" {
        val run = pod("run", script("throws.main.kts"))
        run.exitCode shouldBe 1
        run.out shouldContainExactly listOf("before")
        run.errors.trim() shouldBe "error: latitude must be in -90..90, was 91.0 (throws.main.kts:4)"
    }

    "a program that Pod fails after it suspended is reported at the line of the failing call, not at `pod {`" {
        // PickTimeout is made in the engine's coroutine: the only script frame on its stack is the `pod {` call (line 11).
        val run = pod("run", script("fails-in-program.main.kts"), "--sim", "1", "--time-scale", "10")
        withClue(run.err) {
            run.exitCode shouldBe 1
            run.errors.trim() shouldStartWith "error: pick timed out"
            run.errors.trim() shouldEndWith "(fails-in-program.main.kts:15)"
        }
    }

    "an exception thrown in a function the program calls is reported at that function's line" {
        val run = pod("run", script("fails-in-program.main.kts"), "--sim", "1", "--time-scale", "10", "--", "nested")
        run.exitCode shouldBe 1
        run.errors.trim() shouldBe "error: at most 2 vehicles fly here, asked for 3 (fails-in-program.main.kts:7)"
    }

    "a missing script is a clear error with exit code 2" {
        val run = pod("run", "no-such-script.main.kts", "--sim", "3")
        run.exitCode shouldBe 2
        run.errors.trim() shouldBe "error: no such script: no-such-script.main.kts"
    }

    "the sample script flies Listing 2 under pod run: survey until the battery is low, then home and landed" {
        val sample = File("../samples/scripts/low-battery-survey.main.kts").canonicalPath
        val run = pod("run", sample, "--sim", "1", "--time-scale", "40")
        run.exitCode shouldBe 0
        val survey = run.out.indexOfFirst { it.contains("flies 'survey'") }
        val low = run.out.indexOfFirst { it.contains("coming home") }
        val landed = run.out.indexOfFirst { it.contains("copter-1 landed at home") }
        (survey in 0 until low) shouldBe true
        (low < landed) shouldBe true
        run.out.any { it.contains("cancel survey on [copter-1]") } shouldBe true
        run.out.any { it.contains("done   home on [copter-1]") } shouldBe true
    }

    /**
     * Runs [script] under `pod run --connect` against [count] simulated copters behind a UDP link,
     * started with the link: their home comes only once their estimator has an origin, seconds
     * after their first heartbeat, as on a real autopilot. Their disarm-when-idle is off
     * (DISARM_DELAY 0): at 40x its 10 s would pass before a 1 Hz heartbeat confirms the arming.
     */
    suspend fun connected(script: String, count: Int): Run = coroutineScope {
        val port = freePort()
        val base = SimVehicleConfig(
            systemId = 1, timeScale = 40.0, positionReadyAfter = 20.seconds, gcs = "udpout://127.0.0.1:$port",
            parameters = mapOf("DISARM_DELAY" to 0.0),
        )
        val fleet = SimFleet.start(count, this, base)
        try {
            withContext(Dispatchers.IO) { pod("run", script, "--connect", "udpin://127.0.0.1:$port") }
        } finally {
            fleet.stop()
        }
    }

    "the sample script runs unchanged against vehicles reached with --connect, still booting when it starts" {
        val run = connected(File("../samples/scripts/low-battery-survey.main.kts").canonicalPath, 1)
        withClue({ run.err + run.out.joinToString("\n") }) {
            run.err shouldNotContain "NullPointerException"
            run.exitCode shouldBe 0
            run.out.any { it.contains("copter-1 landed at home") } shouldBe true
        }
    }

    "the README's Programs example runs unchanged against two vehicles reached with --connect" {
        val program = MarkdownKotlin.blocks(File("../README.md")).single { block -> block.code.any { it.startsWith("pod {") } && block.code.none { it.contains("missionQueue") || it.contains("surveyWorkflow(") } }
        val file = Files.createTempFile("readme-programs", ".main.kts").toFile().apply { writeText(program.script) }
        val run = try {
            connected(file.path, 2)
        } finally {
            file.delete()
        }
        withClue({ run.err + run.out.joinToString("\n") }) {
            run.err shouldNotContain "NullPointerException"
            run.exitCode shouldBe 0
            run.out.any { it.contains("done   home on [copter-1]") } shouldBe true
            run.out.any { it.contains("done   home on [copter-2]") } shouldBe true
        }
    }
})
