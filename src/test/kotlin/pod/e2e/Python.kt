package pod.e2e

import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.SharedFlow
import kotlinx.coroutines.flow.asSharedFlow
import kotlinx.coroutines.flow.first
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.jsonObject
import java.io.File
import java.io.IOException
import java.util.concurrent.TimeUnit
import kotlin.concurrent.thread

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

    /**
     * Starts [script] with [args] as a [JsonPeer]: its stdout is read as one JSON object per line,
     * its stderr goes to this process's stderr.
     */
    fun startJson(script: String, vararg args: Any): JsonPeer =
        JsonPeer(
            script,
            ProcessBuilder(listOf(executable, script(script)) + args.map { it.toString() })
                .redirectError(ProcessBuilder.Redirect.INHERIT)
                .start(),
        )

    fun Process.stop() {
        destroy()
        if (!waitFor(5, TimeUnit.SECONDS)) destroyForcibly()
    }
}

/**
 * A Python peer that reports on stdout, one flat JSON object per line with an "event" field
 * (numbers, strings, booleans, NaN; no nesting). Lines that are not JSON are passed to stderr.
 */
internal class JsonPeer(private val name: String, val process: Process) {
    private val _events = MutableSharedFlow<Map<String, String>>(replay = 100_000)

    /** Everything the peer printed so far and from now on. */
    val events: SharedFlow<Map<String, String>> = _events.asSharedFlow()

    init {
        thread(isDaemon = true, name = "$name-stdout") {
            try {
                process.inputStream.bufferedReader().forEachLine { line ->
                    val event = if (line.startsWith("{")) parseFlatJson(line) else null
                    if (event == null || event["event"] != "item") System.err.println("[$name] $line")
                    if (event != null) _events.tryEmit(event)
                }
            } catch (_: IOException) {
                // The process was killed mid-line.
            }
            _events.tryEmit(mapOf("event" to EXITED, "code" to process.waitFor().toString()))
        }
    }

    /**
     * The first event named [event] that satisfies [predicate], printed before or after this call.
     * Throws [AssertionError] if the peer exits without printing it.
     */
    suspend fun await(event: String, predicate: (Map<String, String>) -> Boolean = { true }): Map<String, String> {
        val found = events.first { (it["event"] == event && predicate(it)) || it["event"] == EXITED }
        if (found["event"] == EXITED && event != EXITED) throw AssertionError("$name exited with code ${found["code"]} before printing the \"$event\" event")
        return found
    }

    /** Writes [line] and a newline to the peer's stdin (scripts that pause at a checkpoint read one). */
    fun send(line: String) {
        process.outputStream.write("$line\n".toByteArray())
        process.outputStream.flush()
    }

    /** Closes the peer's stdin (scripts that watch it exit), then ends it if it has not exited within 3 s. */
    fun stop() {
        try {
            process.outputStream.close()
        } catch (_: IOException) {
        }
        if (!process.waitFor(3, TimeUnit.SECONDS)) {
            process.destroy()
            if (!process.waitFor(5, TimeUnit.SECONDS)) process.destroyForcibly()
        }
    }

    companion object {
        /** The event this class adds when the peer's stdout closes, with its exit "code". */
        const val EXITED = "exited"

        /** The fields of a flat JSON object, each value as its text (Python's NaN as "NaN"); null when [line] is not one. */
        private fun parseFlatJson(line: String): Map<String, String>? = try {
            Json.parseToJsonElement(line).jsonObject.mapValues { (_, v) -> if (v is JsonPrimitive) v.content else v.toString() }
        } catch (e: IllegalArgumentException) {
            null // not JSON (SerializationException), or not an object
        }
    }
}
