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
