package pod.e2e.artifacts

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactlyInAnyOrder
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldNotContain
import pod.core.POD_VERSION
import java.io.File

/**
 * The README's "Use Pod in your build" as a user copies it: every Maven and Gradle coordinate it
 * gives is in the installed repository at Pod's version (Gradle is not available here, so its block
 * is checked by its coordinates), the ones without a version are managed by pod-bom, and the
 * repository holds every published module with a pom that names the version itself.
 */
class ReadmeCoordinatesSpec : StringSpec({
    val section = File("../README.md").readText().substringAfter("\n## Use Pod in your build\n").substringBefore("\n## ")
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
        Regex("""<artifactId>([\w-]+)</artifactId>""").findAll(InstalledRepository.file("pod-bom", POD_VERSION, "pom").readText())
            .map { it.groupValues[1] }.toSet() - "pod-bom"
    }

    "the README's Maven and Gradle blocks name the same modules, the BOM at Pod's version and the rest through it" {
        maven.map { it.artifactId } shouldContainExactlyInAnyOrder gradle.map { it.artifactId }
        (maven + gradle).filter { it.version != null }.map { it.artifactId to it.version }.toSet() shouldBe setOf("pod-bom" to POD_VERSION)
        maven.single { it.artifactId == "pod-bom" }.type shouldBe "pom"
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

    "the installed repository holds every published module at Pod's version, nothing else, with flattened poms" {
        File(InstalledRepository.dir, "pod").list()!!.toList() shouldContainExactlyInAnyOrder InstalledRepository.published
        managed shouldBe InstalledRepository.published.toSet() - setOf("pod-parent", "pod-bom")
        InstalledRepository.published.forEach { artifactId ->
            val pom = InstalledRepository.file(artifactId, POD_VERSION, "pom")
            withClue(pom.path) {
                pom.isFile shouldBe true
                pom.readText() shouldNotContain "\${revision}"
                File(pom.path + ".sha1").isFile shouldBe true
            }
            if (artifactId != "pod-parent" && artifactId != "pod-bom") {
                withClue(artifactId) {
                    InstalledRepository.file(artifactId, POD_VERSION, "jar").isFile shouldBe true
                    InstalledRepository.file(artifactId, POD_VERSION, "jar", classifier = "sources").isFile shouldBe true
                }
            }
        }
    }
})
