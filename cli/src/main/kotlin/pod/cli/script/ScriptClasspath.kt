package pod.cli.script

import java.io.File

/**
 * What a script compiles against under `pod run`: this JVM's classpath (Pod, Kotlin, coroutines
 * and the rest of the CLI's runtime) less the compiler and scripting jars, which the script does
 * not need and which would only make every compile slower. kotlin-main-kts adds itself.
 */
internal object ScriptClasspath {
    private val tooling = listOf(
        "kotlin-compiler-embeddable", "kotlin-scripting-", "kotlin-main-kts", "kotlin-daemon-embeddable",
        "kotlin-build-tools-api", "kotlin-script-runtime",
    )

    /** The entries of [classpath] (default: `java.class.path`) that a script should see. */
    fun forScripts(classpath: String = System.getProperty("java.class.path").orEmpty()): List<File> =
        classpath.split(File.pathSeparator).filter { it.isNotBlank() }.map(::File)
            .filter { it.exists() && tooling.none { prefix -> it.name.startsWith(prefix) } }
            .distinct()
}
