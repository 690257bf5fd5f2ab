package pod.e2e.artifacts

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactlyInAnyOrder
import io.kotest.matchers.shouldBe
import pod.core.POD_VERSION
import java.io.File

/**
 * The README's "Use Pod in your build" as a user copies it: every Maven and Gradle coordinate it
 * gives is in the installed repository at Pod's version (Gradle is not available here, so its block
 * is checked by its coordinates), and the ones without a version are managed by pod-bom.
 */
class ReadmeCoordinatesSpec : StringSpec({
    // Up to the next section, or the API reference subsection (another part's text).
    val section = File("../README.md").readText().substringAfter("\n## Use Pod in your build\n").substringBefore("\n## ").substringBefore("\n### API reference")
    fun block(language: String) = Regex("""```$language\n(.*?)\n```""", RegexOption.DOT_MATCHES_ALL).findAll(section).map { it.groupValues[1] }.toList()

    /** A coordinate as written: artifactId and version (null: managed by the BOM). */
    data class Coordinate(val artifactId: String, val version: String?, val type: String = "jar")

    val maven: List<Coordinate> = block("xml").single().let { xml ->
        Regex("""<dependency>(.*?)</dependency>""", RegexOption.DOT_MATCHES_ALL).findAll(xml).map { it.groupValues[1] }.map { dependency ->
            fun tag(name: String) = Regex("""<$name>([^<]*)</$name>""").find(dependency)?.groupValues?.get(1)
            tag("groupId") shouldBe "pod"
            Coordinate(tag("artifactId")!!, tag("version"), tag("type") ?: "jar")
        }.toList()
    }
    val gradle: List<Coordinate> = block("kotlin").single { it.contains("dependencies {") }.let { script ->
        Regex(""""pod:([\w-]+)(?::([\w.-]+))?"""").findAll(script).map { match ->
            val artifactId = match.groupValues[1]
            Coordinate(artifactId, match.groupValues[2].ifEmpty { null }, if (artifactId == "pod-bom") "pom" else "jar")
        }.toList()
    }
    val managed by lazy {
        InstalledRepository.managed(InstalledRepository.file("pod-bom", POD_VERSION, "pom").readText()).filter { it.first == "pod" }.map { it.second }.toSet()
    }

    "the README's Maven and Gradle blocks name the same modules, the BOM at Pod's version and the rest through it" {
        maven.map { it.artifactId } shouldContainExactlyInAnyOrder gradle.map { it.artifactId }
        (maven + gradle).filter { it.version != null }.map { it.artifactId to it.version }.toSet() shouldBe setOf("pod-bom" to POD_VERSION)
        maven.single { it.artifactId == "pod-bom" }.type shouldBe "pom"
        // The prose names the same version: the only x.y.z version in the section is Pod's.
        Regex("""(?<![\d.])\d+\.\d+\.\d+(?![\d.])""").findAll(section).map { it.value }.toSet() shouldBe setOf(POD_VERSION)
    }

    "every coordinate in the README is in the installed repository at Pod's version" {
        val missing = (maven + gradle).distinct().mapNotNull { c ->
            val file = InstalledRepository.file(c.artifactId, c.version ?: POD_VERSION, c.type)
            when {
                !file.isFile -> "${c.artifactId}: no $file"
                c.version == null && c.artifactId !in managed -> "${c.artifactId} has no version and pod-bom does not manage it"
                else -> null
            }
        }
        withClue(InstalledRepository.dir.path) { missing.shouldBeEmpty() }
    }

    "the README's table of artifacts names every module pod-bom manages" {
        val table = Regex("""^\| `(pod-[\w-]+)` \|""", RegexOption.MULTILINE).findAll(section).map { it.groupValues[1] }.toSet()
        table shouldBe managed + "pod-bom"
    }
})
