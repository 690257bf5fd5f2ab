package pod.e2e

import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.parse
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldNotBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.withContext
import pod.cli.Pod
import pod.cli.json.Event
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.attribute.PosixFilePermissions

private const val KEY_HEX = "4f1d2c3b4a59687786950a1b2c3d4e5f60718293a4b5c6d7e8f9011223344556"

private fun keyFile(text: String, mode: String = "rw-------"): Path = Files.createTempFile("pod-signing", ".key").also {
    Files.writeString(it, text)
    Files.setPosixFilePermissions(it, PosixFilePermissions.fromString(mode))
}

/** Real UDP on 127.0.0.1: `pod signing setup` keys a simulated ArduCopter; then only signed commands move it. */
class SigningCliSpec : StringSpec({

    "pod signing setup keys the vehicle: an unsigned pod arm then times out, a signed one arms; the key is never printed" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 71, timeScale = 5.0, gcs = "udpout://127.0.0.1:$port"))
            val key = keyFile("$KEY_HEX\n")
            val printed = Captured()
            try {
                sim.start(this)
                suspend fun pod(vararg args: String, out: Captured = Captured()) = withContext(Dispatchers.IO) {
                    try {
                        Pod(out).parse(args.toList() + listOf("--connect", "udpin:127.0.0.1:$port", "--sysid", "71", "--json"))
                    } finally {
                        printed.lines += out.lines
                    }
                    out.events.last().shouldBeInstanceOf<Event.Done>()
                }
                pod("signing", "setup", "--key-file", key.toString()).action shouldBe "signing-setup"
                pod("param", "set", "DISARM_DELAY", "0", "--key-file", key.toString()).value shouldBe 0.0
                val unsigned = Captured()
                val error = shouldThrow<CliktError> { pod("arm", out = unsigned) }
                error.statusCode shouldBe 1
                error.message!! shouldContain "COMMAND_ACK"
                unsigned.events.last().shouldBeInstanceOf<Event.Error>()
                sim.state.value.armed shouldBe false
                pod("arm", "--key-file", key.toString()).armed shouldBe true
                sim.state.value.armed shouldBe true
                printed.lines.shouldNotBeEmpty()
                for (line in printed.lines) line shouldNotContain KEY_HEX.substring(0, 12)
            } finally {
                sim.stop()
            }
        }
    }

    "a malformed or open key file is a usage error naming the file, before any link opens" {
        for ((file, reason) in listOf(keyFile("not a key") to "32 raw bytes or 64 hexadecimal digits", keyFile(KEY_HEX, "rw-r--r--") to "chmod 600")) {
            val out = Captured()
            val error = shouldThrow<CliktError> {
                withContext(Dispatchers.IO) { Pod(out).parse(listOf("arm", "--key-file", file.toString(), "--connect", "udpin:127.0.0.1:${freePort()}", "--wait", "1s")) }
            }
            error.statusCode shouldBe 2
            error.message!! shouldContain file.toString()
            error.message!! shouldContain reason
            error.message!! shouldNotContain KEY_HEX.substring(0, 12)
        }
    }
})
