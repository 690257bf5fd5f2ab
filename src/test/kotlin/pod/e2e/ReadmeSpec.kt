package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldNotContain
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.runInterruptible
import java.io.File
import java.nio.file.Files
import java.util.concurrent.CompletableFuture

/**
 * The documentation's Kotlin as a reader copies it: every ```kotlin block of README.md and
 * the Markdown files in docs/ compiles under `pod run` (fragments inside the context their `<!-- fragment` comment
 * gives), and the README's "Programs" example flies to completion on simulated drones.
 * The compiles share one JVM and the flights another ([PodBatch]), the two side by side.
 */
class ReadmeSpec : StringSpec({
    val work = Files.createTempDirectory("pod-readme").toFile()
    afterSpec { work.deleteRecursively() }

    val docs = listOf(File("../README.md")) + File("../docs").listFiles { f -> f.name.endsWith(".md") }!!.sorted()
    val blocks = docs.flatMap { MarkdownKotlin.blocks(it, if (it.parentFile.name == "docs") "docs/${it.name}" else it.name) }

    /** The arguments of `pod run` of [block] as a script file. */
    fun runArgs(block: KotlinBlock, vararg options: String): List<String> {
        val script = File(work, "${block.file.replace('/', '-').removeSuffix(".md")}-${block.line}.main.kts")
        script.writeText(block.script)
        return listOf("run", script.path) + options
    }

    val programs = blocks.filter { it.file == "README.md" && it.code.any { line -> line.startsWith("pod {") } }

    // The README's three programs fly one after another in one JVM (a PodBatch), beside the JVM that
    // compiles the other blocks: one JVM and one warm compiler for each group, not one per block.
    val flights: Lazy<CompletableFuture<Map<KotlinBlock, PodRun>>> = lazy {
        val runs = listOf(
            programs.single { block -> block.code.none { it.contains("missionQueue") || it.contains("surveyWorkflow") } } to listOf("--sim", "2", "--time-scale", "100"),
            programs.single { block -> block.code.any { it.contains("surveyWorkflow(") } } to listOf("--sim", "1", "--time-scale", "50"),
            programs.single { block -> block.code.any { it.contains("missionQueue") } } to listOf("--sim", "1", "--time-scale", "50"),
        )
        val args = runs.map { (block, options) -> runArgs(block, *options.toTypedArray()) }
        CompletableFuture.supplyAsync { runs.map { it.first }.zip(PodBatch.run(args, File(work, "cache"))).toMap() }
    }

    /** What `pod run` of the README program [block] printed (the flights run once, for all the tests). */
    fun flown(block: KotlinBlock): PodRun = flights.value.get().getValue(block)

    "every ```kotlin block of the README and docs/ compiles against Pod (fragments in their stated context)" {
        programs shouldHaveSize 3
        flights.value // starts the flights beside the compiles
        val compiled = blocks.filter { it.skipped == null && it.code.none { line -> line.startsWith("pod {") } }
        (compiled.size >= 6) shouldBe true // the README's missions, flying, fleet choice, two app blocks; docs' mission
        // Blocks that are not programs only declare things or print: running them is compiling them.
        val runs = runInterruptible(Dispatchers.IO) { PodBatch.run(compiled.map { runArgs(it) }, File(work, "cache")) }
        val failed = compiled.zip(runs).filter { (_, run) -> run.exitCode != 0 }
            .map { (block, run) -> "${block.where} does not compile:\n${run.err}\n${block.numbered}" }
        withClue(failed.joinToString("\n\n")) { failed.shouldBeEmpty() }
    }

    "the only block not compiled is the Gradle build script, and it says why" {
        blocks.filter { it.skipped != null }.map { it.where to it.skipped } shouldBe
            listOf(blocks.single { it.code.any { line -> line.contains("mavenLocal()") } }.where to "a Gradle build script (build.gradle.kts)")
    }

    "the README's Programs example flies to completion on two simulated drones under pod run" {
        programs shouldHaveSize 3
        val run = runInterruptible(Dispatchers.IO) { flown(programs.single { block -> block.code.none { it.contains("missionQueue") || it.contains("surveyWorkflow") } }) }
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
        val run = runInterruptible(Dispatchers.IO) { flown(survey) }
        withClue({ run.err + run.out.joinToString("\n") }) {
            run.exitCode shouldBe 0
            run.err shouldNotContain "Exception"
            run.out.any { it.contains("done   survey on [copter-1]") } shouldBe true
            run.out.any { Regex("""\d+ photos; revisited waypoints \[\d""").containsMatchIn(it) } shouldBe true
        }
    }

    "the README's mission-queue example flies its queue to the end and lands, on one simulated drone under pod run" {
        val queue = blocks.single { it.file == "README.md" && it.code.any { line -> line.contains("missionQueue") } }
        val run = runInterruptible(Dispatchers.IO) { flown(queue) }
        withClue({ run.err + run.out.joinToString("\n") }) {
            run.exitCode shouldBe 0
            run.err shouldNotContain "Exception"
            run.out.any { it.contains("done   queue on [copter-1]") } shouldBe true
            run.out.any { it.contains("done   home on [copter-1]") } shouldBe true
        }
    }
})
