package pod.e2e.artifacts

import java.io.File
import java.util.concurrent.TimeUnit

/**
 * Runs the Maven that runs this build (`pod.maven.home`, set for the e2e tests) on another project,
 * as a user would run it on theirs: batch mode, no transfer progress, no compile daemon.
 *
 * It resolves into a fresh local repository of its own ([localRepository]), so what the project's
 * build takes is seen in that repository's `_remote.repositories` files. Its repositories are
 * [repositories] (id to file:// URL, searched in that order, before the project's own) and the
 * outer build's local repository, which holds everything Pod's own build downloaded (plugins,
 * Kotlin, kotest); no network is needed. When the outer build is offline this one is too (file://
 * repositories stay usable offline through `aether.offline.protocols`).
 */
internal class NestedMaven(private val work: File, private val repositories: List<Pair<String, String>>) {
    /** The nested build's own local repository. */
    val localRepository: File = File(work, "m2")

    private val settings: File = File(work, "settings.xml")

    init {
        val outer = File(requireNotNull(System.getProperty("pod.maven.localRepository")) { "pod.maven.localRepository is not set: run under Maven" })
        val repos = (repositories + ("outer-local" to outer.toURI().toString())).joinToString("") { (id, url) ->
            "<repository><id>$id</id><url>$url</url></repository>"
        }
        val pluginRepos = "<pluginRepository><id>outer-local</id><url>${outer.toURI()}</url></pluginRepository>"
        settings.writeText(
            """<settings><localRepository>${localRepository.path}</localRepository><profiles><profile><id>repos</id>""" +
                """<repositories>$repos</repositories><pluginRepositories>$pluginRepos</pluginRepositories></profile></profiles>""" +
                """<activeProfiles><activeProfile>repos</activeProfile></activeProfiles></settings>""",
        )
    }

    /** What a run printed and how it exited. */
    class Run(val exitCode: Int, val log: String)

    /** `mvn` with [args] on the project in [project]; the log goes to `work/maven.log` too. */
    fun run(project: File, vararg args: String): Run {
        val home = requireNotNull(System.getProperty("pod.maven.home")) { "pod.maven.home is not set: run under Maven" }
        val offline = System.getProperty("pod.maven.offline") == "offline=true"
        val command = listOf(File(home, "bin/mvn").path, "-B", "-ntp", "-s", settings.path, "-f", File(project, "pom.xml").path) +
            (if (offline) listOf("-o", "-Daether.offline.protocols=file") else emptyList()) +
            listOf("-Dkotlin.compiler.daemon=false") + args
        val log = File(work, "maven.log")
        val process = ProcessBuilder(command).directory(project).redirectErrorStream(true).redirectOutput(log).start()
        // A bound against a hung build, not a timing assertion.
        check(process.waitFor(10, TimeUnit.MINUTES)) { process.destroyForcibly(); "mvn did not finish: ${log.readText()}" }
        return Run(process.exitValue(), log.readText())
    }

    /** The repository ids each resolved file of `group:artifactId:version` came from (`_remote.repositories`). */
    fun origins(artifactId: String, version: String, group: String = "pod"): Map<String, String> {
        val file = File(localRepository, "${group.replace('.', '/')}/$artifactId/$version/_remote.repositories")
        if (!file.isFile) return emptyMap()
        return file.readLines().filter { '>' in it && !it.startsWith("#") }
            .associate { it.substringBefore('>') to it.substringAfter('>').removeSuffix("=") }
    }
}
