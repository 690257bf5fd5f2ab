package pod.e2e.artifacts

import java.io.File

/**
 * The installed repository that Pod's `verify` fills (tools/pod-repo.xml): where it is, and what a
 * user's build finds in it. Its location comes from the build (`pod.repo`, set for the e2e tests);
 * run outside Maven, the default `target/pod-repo` of the checkout.
 */
internal object InstalledRepository {
    /** The published modules, each in the repository at Pod's version. */
    val published: List<String> = listOf("pod-parent", "pod-bom", "pod-core", "pod-dsl", "pod-mavlink", "pod-sim", "pod-launch", "pod-test")

    /** The version properties of the platform pod-bom pins (Kotlin, coroutines, serialization, kotlinx-io). */
    val platformProperties: List<String> = listOf("kotlin.version", "coroutines.version", "serialization.version", "kotlinx-io.version")

    /** The values of [platformProperties] in the pom text [pom]. */
    fun platformVersions(pom: String): Map<String, String?> =
        platformProperties.associateWith { Regex("<${Regex.escape(it)}>([^<]+)</").find(pom)?.groupValues?.get(1) }

    /** The (groupId, artifactId) pairs that the pom text [pom] manages in its dependencyManagement. */
    fun managed(pom: String): Set<Pair<String, String>> =
        Regex("""<dependency>(.*?)</dependency>""", RegexOption.DOT_MATCHES_ALL)
            .findAll(pom.substringAfter("<dependencyManagement>").substringBefore("</dependencyManagement>"))
            .map { d -> listOf("groupId", "artifactId").map { Regex("<$it>([^<]+)</$it>").find(d.value)!!.groupValues[1] } }
            .map { (g, a) -> g to a }.toSet()

    /** The repository's directory; fails, saying how to fill it, when the build has not. */
    val dir: File
        get() {
            val dir = File(System.getProperty("pod.repo") ?: "../target/pod-repo").absoluteFile
            check(File(dir, "pod/pod-core").isDirectory) {
                "no installed repository at $dir: run `./mvnw -B -ntp verify` (or install) on Pod first"
            }
            return dir
        }

    /** The directory of [artifactId] at [version] (group `pod`). */
    fun versionDir(artifactId: String, version: String, group: String = "pod"): File =
        File(dir, "${group.replace('.', '/')}/$artifactId/$version")

    /** The file `artifactId-version[-classifier].extension` in the repository. */
    fun file(artifactId: String, version: String, extension: String, classifier: String? = null, group: String = "pod"): File =
        File(versionDir(artifactId, version, group), "$artifactId-$version${classifier?.let { "-$it" } ?: ""}.$extension")
}
