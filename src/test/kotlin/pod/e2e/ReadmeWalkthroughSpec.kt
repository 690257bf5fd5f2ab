package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.CoroutineExceptionHandler
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.job
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.cli.json.Event
import pod.cli.json.EventJson
import java.io.File
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * The README's `pod` walkthrough as a person runs it, each command a process of its own in its own
 * terminal: `pod watch` keeps showing the vehicle while `pod mode`, `pod arm` and `pod takeoff`
 * run beside it, on the same vehicle.
 */
class ReadmeWalkthroughSpec : StringSpec({

    "no README block runs pod watch beside a command that listens on the same udpin port" {
        val blocks = Regex("```sh\\n(.*?)```", RegexOption.DOT_MATCHES_ALL).findAll(File("../README.md").readText()).map { it.groupValues[1] }
        val clashes = blocks.flatMap { block ->
            val commands = block.lines().flatMap { it.substringBefore(" #").split("&&") }.map { it.trim() }.filter { it.startsWith("./pod ") }
            fun listensOn(command: String): String? {
                val words = command.split(Regex("\\s+"))
                // What opens a vehicle link: watch, mission, param and the vehicle actions; the default is udpin:0.0.0.0:14550.
                if (words.getOrNull(1) in setOf("sim", "replay", "map", "demo", "survey", "run", "route")) return null
                if (words.getOrNull(1) == "queue" && words.getOrNull(2) != "serve") return null
                val connect = words.indexOf("--connect").takeIf { it >= 0 }?.let { words.getOrNull(it + 1) } ?: "udpin:0.0.0.0:14550"
                return connect.replace("udpin://", "udpin:").takeIf { it.startsWith("udpin:") }
            }
            val watched = commands.filter { it.startsWith("./pod watch") }.mapNotNull(::listensOn).toSet()
            commands.filter { !it.startsWith("./pod watch") }.filter { listensOn(it) in watched }
        }.toList()
        withClue("commands that cannot run while pod watch holds their port") { clashes.shouldBeEmpty() }
    }

    "the walkthrough as a person runs it: pod sim with two outputs, pod watch on one, mode, arm and takeoff on the other, all at once" {
        coroutineScope {
            // A process's output readers may end with "Stream closed" when it exits: not this test's failure.
            val processes = CoroutineScope(coroutineContext + SupervisorJob(coroutineContext.job) + CoroutineExceptionHandler { _, _ -> })
            val commands = freePort()
            val watching = freePort()
            val sim = processes.startPod(listOf("sim", "--sysid", "76", "--out", "udpout:127.0.0.1:$commands", "--out", "udpout:127.0.0.1:$watching", "--time-scale", "5"))
            val watch = processes.startPod(listOf("watch", "--connect", "udpin:127.0.0.1:$watching", "--json"))
            try {
                watch.awaitOut(1.minutes) { "\"found\"" in it && "\"sysid\":76" in it }
                for (args in listOf(listOf("param", "set", "DISARM_DELAY", "0"), listOf("mode", "GUIDED"), listOf("arm"), listOf("takeoff", "10"))) {
                    val (code, lines) = runPod(args + listOf("--connect", "udpin:127.0.0.1:$commands", "--json"))
                    withClue("pod ${args.joinToString(" ")}: $lines") { code shouldBe 0 }
                    EventJson.decode(lines.last()).shouldBeInstanceOf<Event.Done>()
                }
                // All the while the watch kept the vehicle, and shows it armed and up.
                withTimeout(30.seconds) {
                    watch.out.first { lines ->
                        lines.filter { it.startsWith("{\"event\":\"telemetry\"") }.map { EventJson.decode(it) as Event.Telemetry }
                            .any { it.sysid == 76 && it.armed && (it.altRel ?: 0.0) > 8.0 }
                    }
                }
                watch.out.value.none { "\"lost\"" in it } shouldBe true
            } finally {
                stopPods(processes, watch, sim)
            }
        }
    }
})

/** Runs `pod ARGS` in a process of its own to its end (at most two minutes): its exit code and stdout lines. */
private suspend fun runPod(args: List<String>): Pair<Int, List<String>> = runInterruptible(Dispatchers.IO) {
    val jvm = File(System.getProperty("java.home"), "bin/java").path
    val process = ProcessBuilder(listOf(jvm, "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "pod.cli.MainKt") + args)
        .redirectError(ProcessBuilder.Redirect.INHERIT).start()
    process.outputStream.close()
    val lines = process.inputStream.bufferedReader().readLines() // until the process closes its stdout
    if (!process.waitFor(2, java.util.concurrent.TimeUnit.MINUTES)) process.destroyForcibly()
    process.exitValue() to lines
}
