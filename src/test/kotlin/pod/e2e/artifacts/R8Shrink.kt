package pod.e2e.artifacts

import java.io.File
import java.util.concurrent.TimeUnit
import java.util.zip.ZipEntry
import java.util.zip.ZipFile
import java.util.zip.ZipOutputStream

/**
 * Shrinks a small app with R8 in class-file mode, as an Android release build would (full mode,
 * names minified), but for the JVM so its output runs here with `java`. R8 (`pod.r8.jar`, copied by
 * the e2e build) runs as a process of its own. Program input: the app's classes, pod-mavlink,
 * pod-core and io.dronefleet's jar, whose embedded rules (META-INF/proguard) R8 reads itself;
 * kotlin-stdlib is a classpath input (the subject is Pod's and io.dronefleet's reflection, and
 * shrinking the stdlib too only costs time).
 */
internal class R8Shrink(private val work: File) {
    private val classpath = System.getProperty("java.class.path").split(File.pathSeparator).map(::File)

    /** The kotlin-stdlib jar on this test's classpath, which the shrunk app runs with. */
    val stdlib: File = jar(Regex("""kotlin-stdlib-\d[^/]*\.jar"""))
    private val annotations = jar(Regex("""annotations-\d[^/]*\.jar"""))
    val mavlink: File = module("pod-mavlink", "mavlink")
    private val core = module("pod-core", "core")
    private val dronefleet = jar(Regex("""mavlink-1\.\d[^/]*\.jar"""))

    /** What R8 said and how it exited. */
    class Result(val exitCode: Int, val log: String, val output: File, val configuration: File)

    /**
     * Shrinks [appClasses] (class files, keeping [mainClass]'s `main`) with [mavlinkJar] in place of
     * pod-mavlink's jar, into `work/<name>.jar`.
     */
    fun shrink(name: String, appClasses: List<File>, mainClass: String, mavlinkJar: File = mavlink): Result {
        val rules = File(work, "$name-app.pro").apply { writeText("-keep class $mainClass { public static void main(java.lang.String[]); }\n") }
        val output = File(work, "$name.jar")
        val configuration = File(work, "$name-configuration.txt")
        val r8 = File(requireNotNull(System.getProperty("pod.r8.jar")) { "pod.r8.jar is not set: run under Maven" })
        val command = listOf(
            javaCommand(), "-cp", r8.path, "com.android.tools.r8.R8", "--classfile", "--release",
            "--lib", System.getProperty("java.home"), "--classpath", annotations.path, "--classpath", stdlib.path,
            "--output", output.path, "--pg-conf", rules.path, "--pg-conf-output", configuration.path,
        ) + appClasses.map { it.path } + listOf(mavlinkJar.path, core.path, dronefleet.path)
        val log = File(work, "$name-r8.log")
        val process = ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log).start()
        // A bound against a hung child, not a timing assertion.
        check(process.waitFor(10, TimeUnit.MINUTES)) { process.destroyForcibly(); "R8 did not finish" }
        return Result(process.exitValue(), log.readText(), output, configuration)
    }

    /** A copy of [jar] without the entries whose names start with [prefix]. */
    fun without(jar: File, prefix: String, name: String): File {
        val copy = File(work, name)
        ZipFile(jar).use { zip ->
            ZipOutputStream(copy.outputStream()).use { out ->
                zip.entries().asSequence().filterNot { it.name.startsWith(prefix) }.forEach { entry ->
                    out.putNextEntry(ZipEntry(entry.name))
                    zip.getInputStream(entry).use { it.copyTo(out) }
                    out.closeEntry()
                }
            }
        }
        return copy
    }

    private fun jar(name: Regex): File = classpath.singleOrNull { name.matches(it.name) }
        ?: error("no single jar named like $name on the test classpath")

    /** A Pod module's jar: from the reactor (module/target) or the local repository; a directory is jarred. */
    private fun module(artifactId: String, moduleDir: String): File {
        val entry = classpath.firstOrNull { it.name.startsWith("$artifactId-") && it.name.endsWith(".jar") && !it.name.endsWith("-tests.jar") }
            ?: classpath.firstOrNull { it.isDirectory && it.path.endsWith("$moduleDir/target/classes") }
            ?: error("$artifactId is not on the test classpath")
        if (entry.isFile) return entry
        val jarred = File(work, "$artifactId.jar")
        ZipOutputStream(jarred.outputStream()).use { out ->
            entry.walk().filter { it.isFile }.forEach { file ->
                out.putNextEntry(ZipEntry(file.relativeTo(entry).invariantSeparatorsPath))
                file.inputStream().use { it.copyTo(out) }
                out.closeEntry()
            }
        }
        return jarred
    }

    companion object {
        /** This JVM's `java`. */
        fun javaCommand(): String = File(System.getProperty("java.home"), "bin/java").path
    }
}
