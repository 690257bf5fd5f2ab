package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldNotContain
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.sync.Semaphore
import kotlinx.coroutines.sync.withPermit
import java.io.File
import java.nio.file.Files
import java.util.concurrent.TimeUnit

/**
 * The documentation's Kotlin as a reader copies it: every ```kotlin block of README.md and
 * the Markdown files in docs/ compiles under `pod run` (fragments inside the context their `<!-- fragment` comment
 * gives), and the README's "Programs" example flies to completion on simulated drones.
 */
class ReadmeSpec : StringSpec({
    val work = Files.createTempDirectory("pod-readme").toFile()
    afterSpec { work.deleteRecursively() }

    val docs = listOf(File("../README.md")) + File("../docs").listFiles { f -> f.name.endsWith(".md") }!!.sorted()
    val blocks = docs.flatMap { MarkdownKotlin.blocks(it, if (it.parentFile.name == "docs") "docs/${it.name}" else it.name) }

    /** `pod run` of [block] as a script file, in a JVM of its own (as ScriptRunSpec starts it). */
    fun run(block: KotlinBlock, vararg options: String): PodRun {
        val script = File(work, "${block.file.replace('/', '-').removeSuffix(".md")}-${block.line}.main.kts")
        script.writeText(block.script)
        return PodRun.start(listOf("run", script.path) + options, cache = File(work, "cache"))
    }

    "every ```kotlin block of the README and docs/ compiles against Pod (fragments in their stated context)" {
        val compiled = blocks.filter { it.skipped == null && it.code.none { line -> line.startsWith("pod {") } }
        (compiled.size >= 6) shouldBe true // the README's missions, flying, fleet choice, two app blocks; docs' mission
        // Blocks that are not programs only declare things or print: running them is compiling them.
        val failed = coroutineScope {
            val cores = Semaphore(2)
            compiled.map { block -> async(Dispatchers.IO) { cores.withPermit { block to run(block) } } }.awaitAll()
        }.filter { (_, run) -> run.exitCode != 0 }
            .map { (block, run) -> "${block.where} does not compile:\n${run.err}\n${block.numbered}" }
        withClue(failed.joinToString("\n\n")) { failed.shouldBeEmpty() }
    }

    "the only block not compiled is the Gradle build script, and it says why" {
        blocks.filter { it.skipped != null }.map { it.where to it.skipped } shouldBe
            listOf(blocks.single { it.code.any { line -> line.contains("mavenLocal()") } }.where to "a Gradle build script (build.gradle.kts)")
    }

    "the README's Programs example flies to completion on two simulated drones under pod run" {
        val programs = blocks.filter { it.file == "README.md" && it.code.any { line -> line.startsWith("pod {") } }
        programs shouldHaveSize 3
        val run = run(programs.single { block -> block.code.none { it.contains("missionQueue") || it.contains("surveyWorkflow") } }, "--sim", "2", "--time-scale", "100")
        withClue({ run.err + run.out.joinToString("\n") }) {
            run.exitCode shouldBe 0
            run.err shouldNotContain "Exception"
            run.out.any { it.contains("done   home on [copter-1]") } shouldBe true
            run.out.any { it.contains("done   home on [copter-2]") } shouldBe true
            run.out.last() shouldBe run.out.last { it.contains("released copter-1, copter-2") }
        }
    }

    "the README's survey-workflow example flies both passes and lands, on one simulated drone under pod run" {
        val survey = blocks.single { it.file == "README.md" && it.code.any { line -> line.contains("surveyWorkflow(") } }
        val run = run(survey, "--sim", "1", "--time-scale", "50")
        withClue({ run.err + run.out.joinToString("\n") }) {
            run.exitCode shouldBe 0
            run.err shouldNotContain "Exception"
            run.out.any { it.contains("done   survey on [copter-1]") } shouldBe true
            run.out.any { Regex("""\d+ photos; revisited waypoints \[\d""").containsMatchIn(it) } shouldBe true
        }
    }

    "the README's mission-queue example flies its queue to the end and lands, on one simulated drone under pod run" {
        val queue = blocks.single { it.file == "README.md" && it.code.any { line -> line.contains("missionQueue") } }
        val run = run(queue, "--sim", "1", "--time-scale", "50")
        withClue({ run.err + run.out.joinToString("\n") }) {
            run.exitCode shouldBe 0
            run.err shouldNotContain "Exception"
            run.out.any { it.contains("done   queue on [copter-1]") } shouldBe true
            run.out.any { it.contains("done   home on [copter-1]") } shouldBe true
        }
    }
})

/** What `pod` printed and how it exited. */
internal class PodRun(val exitCode: Int, val out: List<String>, val err: String) {
    companion object {
        /**
         * Runs `pod` with [args] in a JVM of its own (`pod.cli.MainKt` on this test's classpath, as
         * the `./pod` launcher starts it), scripts cached in [cache].
         */
        fun start(args: List<String>, cache: File): PodRun {
            val dir = Files.createTempDirectory("pod-run").toFile()
            try {
                val java = File(System.getProperty("java.home"), "bin/java").path
                val process = ProcessBuilder(
                    listOf(java, "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "pod.cli.MainKt") + args,
                ).redirectOutput(File(dir, "out")).redirectError(File(dir, "err")).redirectInput(ProcessBuilder.Redirect.PIPE)
                    .also { it.environment()["POD_SCRIPT_CACHE"] = cache.path }
                    .start()
                process.outputStream.close()
                // A bound against a hung child, not a timing assertion.
                check(process.waitFor(5, TimeUnit.MINUTES)) { process.destroyForcibly(); "pod did not finish" }
                return PodRun(process.exitValue(), File(dir, "out").readLines(), File(dir, "err").readText())
            } finally {
                dir.deleteRecursively()
            }
        }
    }
}
