package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.ints.shouldBeGreaterThan
import pod.core.PodException
import java.lang.reflect.Modifier
import java.net.URI
import java.nio.file.FileSystems
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import kotlin.io.path.extension
import kotlin.io.path.invariantSeparatorsPathString

/** Every class of Pod's main code (not its tests), by name, from each module's classes on the class path. */
private fun podMainClasses(): List<String> {
    val loader = PodException::class.java.classLoader
    return loader.getResources("pod/").toList().flatMap { url ->
        val uri = url.toURI()
        val root: Path = when (uri.scheme) {
            "file" -> Paths.get(uri).parent
            "jar" -> FileSystems.newFileSystem(URI.create(uri.toString().substringBefore("!/")), emptyMap<String, Any>()).getPath("/")
            else -> return@flatMap emptyList()
        }
        // Tests' classes, as a directory or as a test jar (pod-mavlink's fuzz harness is one): not main code.
        if ("test-classes" in root.toString() || "-tests.jar" in uri.toString()) return@flatMap emptyList()
        Files.walk(root.resolve("pod")).use { paths ->
            paths.filter { it.extension == "class" }.map { root.relativize(it).invariantSeparatorsPathString.removeSuffix(".class").replace('/', '.') }.toList()
        }
    }.distinct()
}

/**
 * Throwables that are not [PodException] on purpose: cancellation must stay a
 * CancellationException for coroutines to unwind, and a [pod.launch.ProgramLocation] is never
 * thrown (it rides on a failure as a suppressed note naming the program's line).
 */
private val NOT_FAILURES = setOf("pod.launch.Interrupted", "pod.launch.ProgramLocation")

class PodExceptionSpec : StringSpec({

    "every public exception class in Pod's main code extends PodException" {
        val loader = PodException::class.java.classLoader
        val throwables = podMainClasses()
            .map { Class.forName(it, false, loader) }
            .filter { Throwable::class.java.isAssignableFrom(it) && Modifier.isPublic(it.modifiers) }
        // The scan sees the modules: the exceptions of core, mavlink and launch at least.
        throwables.map { it.name } shouldContain "pod.core.vehicle.VehicleLost"
        throwables.map { it.name } shouldContain "pod.mavlink.mission.MissionTimeout"
        throwables.size shouldBeGreaterThan 20
        throwables.filterNot { PodException::class.java.isAssignableFrom(it) || it.name in NOT_FAILURES }.map { it.name }.shouldBeEmpty()
    }
})
