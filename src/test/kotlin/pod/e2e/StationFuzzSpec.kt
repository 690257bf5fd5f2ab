package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.ConnectionState
import pod.mavlink.fuzz.FuzzCorpus
import pod.mavlink.fuzz.Mutator
import pod.sim.SimVehicleConfig
import kotlin.random.Random
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * The whole receive path of a station, not only its decoder: 100k datagrams made by the decoder
 * fuzz harness's mutator (pod-mavlink's test jar) — among them frames that pass their checksum
 * carrying nonsense, from the vehicles' own system ids — thrown at a station flying two simulated
 * vehicles, in virtual time. The frames the decoder passes reach every handler (telemetry, status
 * text, exchanges); none may throw (a handler that did would be counted in `handlerErrors`), and the
 * real vehicles stay connected with their telemetry flowing.
 */
class StationFuzzSpec : StringSpec({

    "100k fuzzed datagrams through a station's whole receive path: no handler throws, the vehicles stay connected" {
        virtualRun(seed = 27, timeout = 4.minutes) {
            coroutineScope {
                val gcs = station(this)
                val fleet = fleet(this, 2, SimVehicleConfig(systemId = 1), gcs)
                try {
                    withTimeout(30.seconds) { gcs.vehicles.first { it.keys.containsAll(setOf(1, 2)) } }
                    val attacker = network.open("udpout://127.0.0.1:${gcs.link.localPort}")
                    val mutator = Mutator(FuzzCorpus(seed = 27).frames)
                    val random = Random(27)
                    repeat(DATAGRAMS) { i ->
                        attacker.sendToAll(mutator.next(random).bytes)
                        // Let the station drain its queue now and then (virtual time), as a socket's reader would.
                        if (i % 50 == 49) delay(1.milliseconds)
                    }
                    val before = listOf(1, 2).associateWith { gcs.vehicles.value.getValue(it).telemetry.linkQuality.value.received }
                    withTimeout(10.seconds) {
                        for ((id, count) in before) gcs.vehicles.value.getValue(id).telemetry.linkQuality.first { it.received > count + 5 }
                    }
                    val stats = withTimeout(5.seconds) { gcs.stats.first { it.frames > DATAGRAMS / 10 } }
                    withClue(stats.toString()) {
                        stats.handlerErrors shouldBe 0
                        stats.badCrc shouldBeGreaterThan 1_000
                        stats.skippedBytes shouldBeGreaterThan 100_000
                    }
                    gcs.linkError.value.shouldBeNull()
                    listOf(1, 2).forEach { gcs.vehicles.value.getValue(it).connection.value shouldBe ConnectionState.CONNECTED }
                    attacker.close()
                } finally {
                    fleet.stop()
                    gcs.close()
                }
            }
        }
    }
}) {
    private companion object {
        const val DATAGRAMS = 100_000
    }
}
