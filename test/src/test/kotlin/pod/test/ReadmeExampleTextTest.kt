package pod.test

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import java.io.File

/**
 * The README's "Test your programs" example is [SurveyPropertySpec] word for word (less its
 * package line), so the test a reader copies is the one the build runs; e2e's ReadmeSpec compiles
 * the README block as a reader's script would.
 */
class ReadmeExampleTextTest : StringSpec({
    "the README's pod-test example is ReadmeExampleSpec.kt without its package line" {
        val readme = File("../README.md").readLines()
        val start = readme.indexOfFirst { it.startsWith("class SurveyPropertySpec") }.let { line -> (line downTo 0).first { readme[it] == "```kotlin" } + 1 }
        val end = (start until readme.size).first { readme[it] == "```" }
        val spec = File("src/test/kotlin/pod/test/ReadmeExampleSpec.kt").readLines().dropWhile { !it.startsWith("import") }
        readme.subList(start, end) shouldBe spec.dropLastWhile { it.isBlank() }
    }
})
