package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withTimeout
import pod.cli.Output
import java.net.DatagramSocket
import java.net.InetAddress
import kotlin.time.Duration.Companion.seconds
import pod.cli.run as runPod

class SimCliSpec : StringSpec({

    "pod sim --vehicles 2 --out udpin:HOST:PORT listens with vehicle i on PORT+i and says so" {
        // Two consecutive free ports.
        val base = generateSequence { freePort() }
            .first { p -> p < 65535 && runCatching { DatagramSocket(p + 1, InetAddress.getByName("127.0.0.1")).close() }.isSuccess }
        val lines = MutableStateFlow<List<String>>(emptyList())
        coroutineScope {
            // pod sim runs until interrupted: this test interrupts it once both vehicles are up.
            val sim = async(Dispatchers.IO) {
                runInterruptible { runPod(listOf("sim", "--vehicles", "2", "--out", "udpin:127.0.0.1:$base"), Output { l -> lines.value += l }, Output { l -> lines.value += l }) }
            }
            val started = withTimeout(20.seconds) { lines.first { it.size >= 2 } }
            sim.cancel()
            started.take(2) shouldBe listOf(
                "vehicle 1: quadrotor on ardupilot, listening on udpin://127.0.0.1:$base",
                "vehicle 2: quadrotor on ardupilot, listening on udpin://127.0.0.1:${base + 1}",
            )
        }
    }
})
