package pod.sim

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import java.net.DatagramSocket
import java.net.InetAddress
import kotlin.time.Duration.Companion.seconds

class SimFleetListenSpec : StringSpec({

    "a listening fleet gives vehicle i its own port, base port + i, as SITL's instances each take one" {
        coroutineScope {
            // Two consecutive free ports: bind one, try the next.
            val base = generateSequence { DatagramSocket(0, InetAddress.getByName("127.0.0.1")).use { it.localPort } }
                .first { p -> p < 65535 && runCatching { DatagramSocket(p + 1, InetAddress.getByName("127.0.0.1")).close() }.isSuccess }
            val fleet = SimFleet.start(2, this, SimVehicleConfig(systemId = 1, gcs = "udpin:127.0.0.1:$base"))
            val gcs = GroundStation.open("udpout:127.0.0.1:${base + 1}", this)
            try {
                fleet.vehicles.map { it.localPort } shouldBe listOf(base, base + 1)
                fleet.vehicles.map { it.config.gcs } shouldBe listOf("udpin://127.0.0.1:$base", "udpin://127.0.0.1:${base + 1}")
                // A ground station sending to base + 1 finds vehicle 2 there.
                withTimeout(10.seconds) { gcs.vehicles.first { it.isNotEmpty() } }.keys shouldBe setOf(2)
            } finally {
                gcs.close()
                fleet.stop()
            }
        }
    }
})
