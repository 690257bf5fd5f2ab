package pod.e2e

import com.github.ajalt.clikt.core.parse
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import pod.cli.Pod
import pod.cli.json.Event
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.io.File
import kotlin.time.Duration.Companion.seconds

/**
 * The README's `pod` walkthroughs as a new user runs them, each command in its own terminal: a
 * `udpin` port takes one listener, so `pod watch` and the commands beside it need links of their own.
 */
class ReadmeWalkthroughSpec : StringSpec({

    "no README block runs pod watch beside a command that listens on the same udpin port" {
        val blocks = Regex("```sh\\n(.*?)```", RegexOption.DOT_MATCHES_ALL).findAll(File("../README.md").readText()).map { it.groupValues[1] }
        val clashes = blocks.flatMap { block ->
            val commands = block.lines().flatMap { it.substringBefore(" #").split("&&") }.map { it.trim() }.filter { it.startsWith("./pod ") }
            fun listensOn(command: String): String? {
                val words = command.split(Regex("\\s+"))
                // What opens a vehicle link: watch, mission, param and the vehicle actions; the default is udpin:0.0.0.0:14550.
                if (words.getOrNull(1) in setOf("sim", "replay", "map", "demo", "survey", "run", "queue")) return null
                val connect = words.indexOf("--connect").takeIf { it >= 0 }?.let { words.getOrNull(it + 1) } ?: "udpin:0.0.0.0:14550"
                return connect.replace("udpin://", "udpin:").takeIf { it.startsWith("udpin:") }
            }
            val watched = commands.filter { it.startsWith("./pod watch") }.mapNotNull(::listensOn).toSet()
            commands.filter { !it.startsWith("./pod watch") }.filter { listensOn(it) in watched }
        }.toList()
        withClue("commands that cannot run while pod watch holds their port") { clashes.shouldBeEmpty() }
    }

    "the documented way works: a listening vehicle, pod watch and a command on udpout links of their own, at once" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 75, gcs = "udpin://127.0.0.1:$port"))
            try {
                sim.start(this)
                val link = listOf("--connect", "udpout:127.0.0.1:$port", "--json")
                val watch = Captured()
                val watching = async(Dispatchers.IO) { Pod(watch).parse(listOf("watch", "--duration", "8s") + link) }
                withTimeout(8.seconds) { watch.eventsOf<Event.Found>().first() }.sysid shouldBe 75
                val mode = Captured()
                withContext(Dispatchers.IO) { Pod(mode).parse(listOf("mode", "GUIDED") + link) }
                mode.events.last().shouldBeInstanceOf<Event.Done>().mode shouldBe "GUIDED"
                watching.await()
                sim.state.value.modeName shouldBe "GUIDED"
            } finally {
                sim.stop()
            }
        }
    }
})
