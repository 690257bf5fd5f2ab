package pod.e2e.artifacts

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import pod.core.POD_VERSION
import pod.e2e.MarkdownKotlin
import java.io.File
import java.nio.file.Files
import java.util.concurrent.TimeUnit

/**
 * Pod as a dependency, the way a user's build takes it: the consumer project
 * (src/test/resources/consumer) imports pod-bom from the installed repository, compiles a program
 * and kotest property tests written with pod-test (its own, and the README's pod-test example copied
 * in as a reader would), and `mvn verify` builds it; the program then
 * flies on `simulate`. Every Pod artifact the build used must have come from the installed
 * repository, none from the local repository Pod's own build installs into.
 *
 * One nested Maven run (two Kotlin compiles, one kotest run) and one program run.
 */
class ConsumerBuildSpec : StringSpec({
    val work = Files.createTempDirectory("pod-consumer").toFile()
    afterSpec { work.deleteRecursively() }

    val project = File(work, "fleet")
    File("../src/test/resources/consumer").copyRecursively(project)
    // The README's pod-test example, as a reader copies it into their project.
    val example = MarkdownKotlin.blocks(File("../README.md")).single { block -> block.code.any { Regex("""^class \w+Spec\b""").containsMatchIn(it) } }
    File(project, "src/test/kotlin/ReadmeExample.kt").writeText(example.code.joinToString("\n", postfix = "\n"))
    val maven = NestedMaven(work, listOf("pod-repo" to InstalledRepository.dir.toURI().toString()))
    val build by lazy {
        maven.run(project, "verify", "-Dpod.version=$POD_VERSION", "-Dpod.repo.url=${InstalledRepository.dir.toURI()}")
    }

    "the consumer project builds against the installed repository through pod-bom" {
        withClue({ build.log }) {
            build.exitCode shouldBe 0
            build.log shouldContain "BUILD SUCCESS"
        }
    }

    "every Pod artifact the consumer used came from the installed repository, at Pod's version" {
        build.exitCode shouldBe 0
        val used = File(maven.localRepository, "pod").listFiles()!!.map { it.name }
        used shouldContainAll listOf("pod-bom", "pod-parent", "pod-core", "pod-dsl", "pod-mavlink", "pod-sim", "pod-launch", "pod-test")
        val wrong = used.flatMap { artifactId ->
            val versions = File(maven.localRepository, "pod/$artifactId").listFiles { f -> f.isDirectory }!!.map { it.name }
            versions.flatMap { version ->
                val origins = maven.origins(artifactId, version)
                val problems = mutableListOf<String>()
                if (version != POD_VERSION) problems += "$artifactId $version is not Pod's version $POD_VERSION"
                if (origins.isEmpty()) problems += "$artifactId $version has no recorded origin"
                origins.filterValues { it != "pod-repo" }.forEach { (file, repo) -> problems += "$file came from $repo" }
                // Byte for byte what the installed repository holds.
                origins.keys.forEach { name ->
                    val installed = File(InstalledRepository.versionDir(artifactId, version), name)
                    val resolved = File(maven.localRepository, "pod/$artifactId/$version/$name")
                    if (!installed.readBytes().contentEquals(resolved.readBytes())) problems += "$name differs from the installed one"
                }
                problems
            }
        }
        withClue(maven.localRepository.path) { wrong.shouldBeEmpty() }
    }

    "the consumer's kotest property tests written with pod-test, the README's example among them, ran and passed" {
        build.exitCode shouldBe 0
        // Every spec class of the project's tests, by its qualified name (the package line, if any, and the class).
        val specs = File(project, "src/test/kotlin").walk().filter { it.name.endsWith(".kt") }.flatMap { file ->
            val text = file.readText()
            val prefix = Regex("""^package ([\w.]+)""", RegexOption.MULTILINE).find(text)?.let { it.groupValues[1] + "." }.orEmpty()
            Regex("""^class (\w+Spec)\b""", RegexOption.MULTILINE).findAll(text).map { prefix + it.groupValues[1] }
        }.toList()
        specs shouldContainAll listOf("example.fleet.HopSpec", "SurveyPropertySpec")
        specs.forEach { spec ->
            val report = File(project, "target/surefire-reports/TEST-$spec.xml")
            withClue("surefire report of $spec") { report.isFile shouldBe true }
            val suite = Regex("""<testsuite [^>]*""").find(report.readText())!!.value
            fun count(name: String) = Regex("""\b$name="(\d+)"""").find(suite)!!.groupValues[1].toInt()
            withClue(suite) {
                count("tests") shouldBeGreaterThan 0
                count("failures") shouldBe 0
                count("errors") shouldBe 0
                count("skipped") shouldBe 0
            }
        }
        File(project, "target/surefire-reports/TEST-example.fleet.HopSpec.xml").readText() shouldContain "for any home, height and leg"
    }

    "the consumer's program flies a mission on simulate" {
        build.exitCode shouldBe 0
        val jars = File(project, "target/classpath.txt").readText().trim().split(File.pathSeparator)
        // The program runs on what the consumer's build resolved, nothing of Pod's own build.
        jars.filterNot { it.startsWith(maven.localRepository.path + File.separator) }.shouldBeEmpty()
        // pod-bom's platform, not the older Kotlin libraries kotest brings.
        val platform = InstalledRepository.platformVersions(InstalledRepository.file("pod-bom", POD_VERSION, "pom").readText())
        val names = jars.map { File(it).name }
        names shouldContain "kotlin-stdlib-${platform["kotlin.version"]}.jar"
        names shouldContain "kotlinx-coroutines-core-jvm-${platform["coroutines.version"]}.jar"
        names shouldContain "kotlinx-serialization-core-jvm-${platform["serialization.version"]}.jar"
        names shouldContain "kotlinx-io-core-jvm-${platform["kotlinx-io.version"]}.jar"
        val classpath = (listOf(File(project, "target/classes").path) + jars).joinToString(File.pathSeparator)
        val out = File(work, "program.out")
        val java = File(System.getProperty("java.home"), "bin/java").path
        val process = ProcessBuilder(java, "-cp", classpath, "example.fleet.HopKt").redirectErrorStream(true).redirectOutput(out).start()
        // A bound against a hung child, not a timing assertion.
        check(process.waitFor(5, TimeUnit.MINUTES)) { process.destroyForcibly(); "the program did not finish" }
        val lines = out.readLines()
        withClue(lines.joinToString("\n")) {
            process.exitValue() shouldBe 0
            lines.any { Regex("""done\s+hop on \[copter-\d]""").containsMatchIn(it) } shouldBe true
            lines.last() shouldBe lines.single { Regex("""fleet: copter-\d flew 1 mission\(s\) on simulate""").matches(it) }
        }
    }
})
