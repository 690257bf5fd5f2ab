package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.comparables.shouldBeGreaterThan
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
 * uploads a 10–20 item mission and downloads it back, and must get back exactly what it sent.
 */
class MavsdkLossyTransferSpec : StringSpec({

    for (loss in listOf(0.1, 0.3)) {
        "through a link losing ${(loss * 100).toInt()} % each way, 20 uploads and 20 downloads with MAVSDK's vehicle side all succeed, each verified" {
            coroutineScope {
                // Heartbeats cross the lossy relay too: allow more silence before calling the vehicle lost.
                val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(lostAfter = 15.seconds))
                val faults = LinkFaults(drop = loss, delay = 1.milliseconds)
                val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:${gcs.link.localPort}", faults, faults, seed = (loss * 100).toLong())
                relay.start(this)
                val peer = Python.startJson("mavsdk_vehicle.py", relay.portA, MAVSDK_VEHICLE_SYSID, 300)
                val failures = ArrayList<String>()
                val took = ArrayList<Long>()
                try {
                    withTimeout(15.seconds) { peer.await("ready") }
                    val vehicle = withTimeout(20.seconds) { gcs.vehicles.first { MAVSDK_VEHICLE_SYSID in it } }.getValue(MAVSDK_VEHICLE_SYSID)
                    val started = TimeSource.Monotonic.markNow()
                    withTimeout(170.seconds) {
                        for (round in 1..20) {
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
                    println("MAVSDK at ${(loss * 100).toInt()} % loss: 20 rounds in ${started.elapsedNow()}, per round (ms) ${took.sorted()}")
                    withClue("failed transfers") { failures.shouldBeEmpty() }
                    relay.counters.value.aToB.dropped shouldBeGreaterThan 10
                } finally {
                    peer.stop()
                    relay.close()
                    gcs.close()
                }
            }
        }
    }
})
