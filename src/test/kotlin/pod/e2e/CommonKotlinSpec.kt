package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import org.jetbrains.kotlin.cli.common.ExitCode
import org.jetbrains.kotlin.cli.jvm.K2JVMCompiler
import org.jetbrains.kotlin.cli.metadata.KotlinMetadataCompiler
import java.io.ByteArrayOutputStream
import java.io.File
import java.io.PrintStream

/**
 * The build's common-Kotlin check (tools/common-kotlin.xml) rejects each JVM-only use the old text
 * check let through. Each planted use is compiled alone with the arguments file core's and dsl's
 * builds wrote and compiled with (`target/common-kotlin/compile.args`: the same klibs, the same
 * target platforms), by the same compiler class in this JVM; each is valid JVM Kotlin, so only
 * its being JVM-only can fail it.
 */
class CommonKotlinSpec : StringSpec({
    val work = tempdir()

    /** The arguments file a module's build wrote for its common compile. */
    fun args(module: String): File = File("../$module/target/common-kotlin/compile.args").also {
        check(it.isFile) { "${it.path} is missing: build $module first (its common-kotlin check writes it)" }
    }

    /** The common compile of [source] alone, as [module]'s build runs it on its sources. */
    fun compileCommon(module: String, name: String, source: String): Pair<ExitCode, String> {
        val dir = File(work, name).apply { mkdirs() }
        val file = File(dir, "Planted.kt").apply { writeText(source) }
        val messages = ByteArrayOutputStream()
        val exit = KotlinMetadataCompiler().exec(
            PrintStream(messages, true), "@${args(module).absolutePath}",
            "-module-name", name, "-d", File(dir, "klib").path, file.path,
        )
        return exit to messages.toString()
    }

    // Each plant: its source (the JVM-only use on line 3) and the error that must name it.
    val plants = mapOf(
        "System.currentTimeMillis()" to ("fun now(): Long =\n    System.currentTimeMillis()" to "3:5: error: unresolved reference 'System'"),
        "Math.abs(x)" to ("fun distance(x: Int): Int =\n    Math.abs(x)" to "3:5: error: unresolved reference 'Math'"),
        "@Synchronized" to ("class Counter {\n    @Synchronized fun next(): Int = 1\n}" to "3:6: error: unresolved reference 'Synchronized'"),
        "Thread" to ("fun threadName(): String =\n    Thread.currentThread().name" to "3:5: error: unresolved reference 'Thread'"),
        "a java.util.concurrent import" to (
            "import java.util.concurrent.ConcurrentHashMap\nval seen = ConcurrentHashMap<String, Int>()" to
                "2:8: error: unresolved reference 'java'"
            ),
    )
    val header = "package planted\n"

    plants.forEach { (use, plant) ->
        val (body, error) = plant
        "core's common compile fails on $use, naming it" {
            val name = "plant-" + use.filter { it.isLetter() }.lowercase()
            val (exit, messages) = compileCommon("core", name, header + body)
            withClue(messages) {
                exit shouldBe ExitCode.COMPILATION_ERROR
                messages shouldContain "Planted.kt:$error"
            }
        }
    }

    "every plant is valid JVM Kotlin: the JVM compiler takes all of them together" {
        val dir = File(work, "jvm").apply { mkdirs() }
        val files = plants.values.mapIndexed { i, (body) -> File(dir, "Plant$i.kt").apply { writeText("package plant$i\n$body") } }
        val stdlib = File(Unit::class.java.protectionDomain.codeSource.location.toURI())
        val messages = ByteArrayOutputStream()
        val exit = K2JVMCompiler().exec(
            PrintStream(messages, true),
            *(listOf("-no-stdlib", "-no-reflect", "-classpath", stdlib.path, "-d", File(dir, "classes").path) + files.map { it.path }).toTypedArray(),
        )
        withClue(messages.toString()) { exit shouldBe ExitCode.OK }
    }

    "core's common compile passes the common equivalents (kotlin.time, kotlin.math, atomics, coroutines)" {
        val source = header + """
            import kotlin.concurrent.atomics.AtomicInt
            import kotlin.concurrent.atomics.ExperimentalAtomicApi
            import kotlin.math.abs
            import kotlin.time.TimeSource
            import kotlinx.coroutines.delay
            import kotlinx.coroutines.sync.Mutex
            import kotlinx.coroutines.sync.withLock

            val started = TimeSource.Monotonic.markNow()
            fun distance(x: Int): Int = abs(x)
            @OptIn(ExperimentalAtomicApi::class)
            val next = AtomicInt(0)
            val lock = Mutex()
            suspend fun pause(): Unit = lock.withLock { delay(10) }
        """.trimIndent()
        val (exit, messages) = compileCommon("core", "clean", source)
        withClue(messages) {
            exit shouldBe ExitCode.OK
            messages shouldNotContain "error:"
        }
    }

    "dsl's common compile sees core's common output, and core's own does not see dsl's" {
        val usesCore = header + "import pod.core.units.Distance\nfun far(d: Distance): Boolean = d > d"
        compileCommon("dsl", "uses-core", usesCore).first shouldBe ExitCode.OK
        val usesDsl = header + "import pod.dsl.mission.mission\nval m = mission { }"
        val (exit, messages) = compileCommon("core", "uses-dsl", usesDsl)
        withClue(messages) {
            exit shouldBe ExitCode.COMPILATION_ERROR
            messages shouldContain "Planted.kt:2:8: error: unresolved reference 'pod'"
        }
    }
})
