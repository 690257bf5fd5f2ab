package pod.e2e.artifacts

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainExactlyInAnyOrder
import io.kotest.matchers.maps.shouldNotContainValue
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldNotContain
import pod.core.POD_VERSION
import java.io.File

/**
 * What `verify` leaves in the installed repository, and what pod-bom promises: every published
 * module at Pod's version with a pom that names the version itself (never `${revision}`), and the
 * Kotlin platform pinned at the versions Pod's own build uses.
 */
class PodBomSpec : StringSpec({
    "the installed repository holds every published module at Pod's version, nothing else, with flattened poms" {
        File(InstalledRepository.dir, "pod").list()!!.toList() shouldContainExactlyInAnyOrder InstalledRepository.published
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

    "pod-bom manages every published library module" {
        val bom = InstalledRepository.file("pod-bom", POD_VERSION, "pom").readText()
        InstalledRepository.managed(bom).filter { it.first == "pod" }.map { it.second } shouldContainExactlyInAnyOrder
            InstalledRepository.published - setOf("pod-parent", "pod-bom")
    }

    "pod-bom pins the Kotlin platform at the versions Pod's build uses" {
        val bom = InstalledRepository.platformVersions(InstalledRepository.file("pod-bom", POD_VERSION, "pom").readText())
        bom shouldNotContainValue null
        bom shouldBe InstalledRepository.platformVersions(File("../pom.xml").readText())
    }
})
