package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactlyInAnyOrder
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import org.jetbrains.kotlin.psi.KtFile
import java.io.File

/** The published library modules whose API the Dokka site documents (directory names; artifact `pod-<name>`). */
private val LIBRARY_MODULES = listOf("core", "dsl", "mavlink", "sim", "launch", "test")

/** Where a module's Dokka includes file (module and package overviews) lives. */
private fun includesFile(module: String) = File("../$module/src/main/docs/packages.md")

/**
 * The API site reads as a reference: every public declaration of the library modules has KDoc,
 * and every package with public API has an overview in its module's Dokka includes file. Parsed
 * from source with the Kotlin compiler's PSI, so it takes seconds and needs no Dokka run.
 */
class ApiDocsSpec : StringSpec({
    val coverage = KDocCoverage()
    afterSpec { coverage.close() }

    /** Every main Kotlin file of each module (src/main/kotlin and the generated-source template), parsed once. */
    val sources: Map<String, List<Pair<String, KtFile>>> by lazy {
        LIBRARY_MODULES.associateWith { module ->
            File("../$module/src/main").walkTopDown().filter { it.isFile && it.extension == "kt" }.sorted()
                .map { it.invariantSeparatorsPath.removePrefix("../") to coverage.parse(it.name, it.readText()) }
                .toList()
        }
    }

    "every public declaration of core, dsl, mavlink, sim, launch and test has KDoc" {
        val files = sources.values.flatten()
        files.size shouldBeGreaterThan 300
        files.flatMap { (path, file) -> coverage.syntaxErrors(file, path) }.shouldBeEmpty()
        val missing = files.flatMap { (path, file) -> coverage.undocumented(file, path) }
        withClue("${missing.size} public declarations without KDoc:\n" + missing.joinToString("\n")) { missing.shouldBeEmpty() }
    }

    "every package with public API has an overview in its module's includes file" {
        val problems = LIBRARY_MODULES.flatMap { module ->
            val packages = sources.getValue(module).map { it.second }.filter(coverage::hasApi).map { it.packageFqName.asString() }.toSet()
            val includes = includesFile(module)
            if (!includes.isFile) listOf("$module: no includes file ${includes.path}")
            else PackageOverviews.problems("pod-$module", includes.readText(), packages)
        }
        withClue(problems.joinToString("\n")) { problems.shouldBeEmpty() }
    }

    "the KDoc check reports an undocumented public function and what else a reader would miss, and nothing that is not API" {
        val source = """
            package planted

            /**
             * A documented class.
             *
             * @property documented what the tag says.
             */
            public class Documented(public val documented: Int, public val bare: Int, private val hidden: Int) {
                public fun undocumentedMember(): Unit = Unit
                override fun toString(): String = "inherits its docs"
                private fun privateHelper(): Unit = Unit
                protected fun protectedInFinalClass(): Unit = Unit
            }

            public fun undocumented(): Int = 1

            /** Says what it does. */
            public fun documented(): Int = 2

            /**
             * @return only a tag, no description.
             */
            public fun tagsOnly(): Int = 3

            internal class Hidden { public fun insideInternal(): Unit = Unit }

            /** An enum. */
            public enum class Mode { /** Documented. */ A, B }

            /** Open. */
            public abstract class Base { protected abstract fun forSubclasses(): Int }

            public fun withLocal(): Int { fun local(): Int = 4; return local() }
        """.trimIndent()
        val found = coverage.undocumented(coverage.parse("Planted.kt", source), "Planted.kt")
        found.map { it.what } shouldContainExactlyInAnyOrder listOf(
            "val Documented.bare", "fun Documented.undocumentedMember", "fun undocumented", "fun tagsOnly",
            "enum entry Mode.B", "fun Base.forSubclasses", "fun withLocal",
        )
        found.single { it.what == "fun undocumented" }.toString() shouldBe "Planted.kt:15 fun undocumented"
    }

    "the overview check reports a missing package, an empty overview, a stale one and a missing module section" {
        val includes = """
            # Package pod.a

            What pod.a is for.

            # Package pod.b

            # Package pod.gone

            Was here once.
        """.trimIndent()
        PackageOverviews.problems("pod-x", includes, setOf("pod.a", "pod.b", "pod.c")) shouldContainExactlyInAnyOrder listOf(
            "pod-x: no `# Module pod-x` overview",
            "pod-x: the overview of pod.b is empty",
            "pod-x: no `# Package pod.c` overview",
            "pod-x: `# Package pod.gone` names no package with public API",
        )
    }
})
