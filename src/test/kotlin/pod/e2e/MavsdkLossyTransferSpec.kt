package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.comparables.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.sim.fault.LinkFaults
import pod.sim.fault.LossyRelay
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * MAVSDK 4.1's vehicle-side mission server behind a relay that loses datagrams each way. It serves
 * downloads only in order (a request past its next item is ignored: "sequence incorrect") and
 * drops a transfer after a few repeats ("timeout: retries exceeded"), whatever its heartbeat says:
 * Pod must learn that from what it does and start over when it drops out. Each of the 20 rounds
 * uploads a 10–20 item mission and downloads it back, and must get back exactly what it sent; the
 * 20 rounds run on four vehicles at once, each behind its own relay.
 */
class MavsdkLossyTransferSpec : StringSpec({

    for (loss in listOf(0.1, 0.3)) {
        "through a link losing ${(loss * 100).toInt()} % each way, 20 uploads and 20 downloads with MAVSDK's vehicle side all succeed, each verified" {
            // MAVSDK paces a lossy transfer with its own 0.5 s timers, so the rounds wait, not compute:
            // four vehicles, each behind its own lossy relay, take five rounds each at once.
            val lanes = coroutineScope {
                (0 until LANES).map { lane -> async { lane(loss, seed = (loss * 100).toLong() * 10 + lane, rounds = (lane * ROUNDS_PER_LANE + 1)..((lane + 1) * ROUNDS_PER_LANE)) } }.awaitAll()
            }
            println("MAVSDK at ${(loss * 100).toInt()} % loss: per round (ms) ${lanes.flatMap { it.took }.sorted()}")
            withClue("failed transfers") { lanes.flatMap { it.failures }.shouldBeEmpty() }
            lanes.sumOf { it.took.size } shouldBe 20
            lanes.forEach { it.dropped shouldBeGreaterThan 2 }
        }
    }
})

private const val LANES = 4
private const val ROUNDS_PER_LANE = 5

private class Lane(val failures: List<String>, val took: List<Long>, val dropped: Long)

/** One MAVSDK vehicle behind a relay losing [loss] each way: upload and download back, once per round. */
private suspend fun lane(loss: Double, seed: Long, rounds: IntRange): Lane = coroutineScope {
    // Heartbeats cross the lossy relay too: allow more silence before calling the vehicle lost.
    val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(lostAfter = 15.seconds))
    val faults = LinkFaults(drop = loss, delay = 1.milliseconds)
    val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:${gcs.link.localPort}", faults, faults, seed = seed)
    relay.start(this)
    val peer = Python.startJson("mavsdk_vehicle.py", relay.portA, MAVSDK_VEHICLE_SYSID, 300)
    val failures = ArrayList<String>()
    val took = ArrayList<Long>()
    try {
        withTimeout(20.seconds) { peer.await("ready") }
        val vehicle = withTimeout(20.seconds) { gcs.vehicles.first { MAVSDK_VEHICLE_SYSID in it } }.getValue(MAVSDK_VEHICLE_SYSID)
        withTimeout(150.seconds) {
            for (round in rounds) {
                // A different list each round, so that a stale download cannot pass for the new one.
                val items = variedMission(10 + round % 11).map { it.copy(z = it.z + round) }
                val mark = TimeSource.Monotonic.markNow()
                try {
                    vehicle.mission.upload(items)
                } catch (e: pod.mavlink.mission.MissionException) {
                    failures += "round $round upload: ${e.message}"
                    continue
                }
                try {
                    val back = vehicle.mission.download()
                    if (back != items) failures += "round $round download differs: ${back.size} items for ${items.size}"
                } catch (e: pod.mavlink.mission.MissionException) {
                    failures += "round $round download: ${e.message}"
                }
                took += mark.elapsedNow().inWholeMilliseconds
            }
        }
        Lane(failures, took, relay.counters.value.aToB.dropped)
    } finally {
        peer.stop()
        relay.close()
        gcs.close()
    }
}
