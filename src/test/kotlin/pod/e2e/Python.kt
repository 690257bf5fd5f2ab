package pod.e2e

import java.io.File
import java.util.concurrent.TimeUnit

/**
 * The Python that has the reference peers (pymavlink, mavsdk): `$POD_PYTHON`, or the `.venv` that
 * `.ci/run` creates at the repository root.
 */
internal object Python {
    val executable: String by lazy {
        System.getenv("POD_PYTHON")?.takeIf { it.isNotBlank() }
            ?: generateSequence(File(System.getProperty("user.dir")).absoluteFile) { it.parentFile }
                .map { File(it, ".venv/bin/python") }
                .firstOrNull { it.canExecute() }?.path
            ?: error("no Python with pymavlink: run .ci/run once (it creates .venv) or set POD_PYTHON")
    }

    /** A test script from src/test/python. */
    fun script(name: String): String =
        generateSequence(File(System.getProperty("user.dir")).absoluteFile) { it.parentFile }
            .map { File(it, "src/test/python/$name") }
            .first { it.isFile }.path

    /** Starts [script] with [args]; its output goes to this process's stderr for diagnosis. */
    fun start(script: String, vararg args: Any): Process =
        ProcessBuilder(listOf(executable, script(script)) + args.map { it.toString() })
            .redirectOutput(ProcessBuilder.Redirect.INHERIT)
            .redirectError(ProcessBuilder.Redirect.INHERIT)
            .start()

    fun Process.stop() {
        destroy()
        if (!waitFor(5, TimeUnit.SECONDS)) destroyForcibly()
    }
}
