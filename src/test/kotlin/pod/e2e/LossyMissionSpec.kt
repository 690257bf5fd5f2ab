package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.Autopilot
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.mission.MissionType
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import pod.sim.fault.LossyRelay
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

class LossyMissionSpec : StringSpec({

    // PX4 serves downloads strictly in order and drops the transfer at the first request out of
    // turn, so over a link that reorders a PX4 download may end in a typed failure, as it does for
    // every ground station: the full fault mix runs against the ArduPilot flavour.
    val cases = listOf(
        Triple(Autopilot.ARDUPILOT, "losing 30% of datagrams each way", LinkFaults(drop = 0.3, delay = 2.milliseconds)),
        Triple(Autopilot.PX4, "losing 30% of datagrams each way", LinkFaults(drop = 0.3, delay = 2.milliseconds)),
        Triple(
            Autopilot.ARDUPILOT,
            "losing 30%, duplicating 5%, reordering 5% and corrupting 1% of datagrams each way",
            LinkFaults(drop = 0.3, duplicate = 0.05, reorder = 0.05, corrupt = 0.01, delay = 2.milliseconds, jitter = 1.milliseconds),
        ),
    )
    for ((autopilot, what, faults) in cases) {
        "through a relay $what, 100 items reach a ${autopilot.name} vehicle and come back identical" {
            coroutineScope {
                // Heartbeats cross the same lossy relay: allow more silence before calling the vehicle lost.
                val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(lostAfter = 10.seconds))
                val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:${gcs.link.localPort}", faults, faults, seed = 7)
                relay.start(this)
                val sim = SimVehicle(SimVehicleConfig(systemId = 21, autopilot = autopilot, gcs = "udpout://127.0.0.1:${relay.portA}"))
                try {
                    sim.start(this)
                    val vehicle = withTimeout(15.seconds) { gcs.vehicles.first { 21 in it } }.getValue(21)
                    val items = waypoints(100)
                    withTimeout(120.seconds) {
                        vehicle.mission.upload(items)
                        val onBoard = sim.missionServer.list(MissionType.MISSION)
                        onBoard.drop(1) shouldBe items.drop(1).map { it.copy(current = false) }
                        vehicle.mission.download() shouldBe onBoard.mapIndexed { i, it -> it.copy(current = i == 0) }
                    }
                    relay.counters.value.aToB.dropped shouldBeGreaterThan 20
                    relay.counters.value.bToA.dropped shouldBeGreaterThan 20
                } finally {
                    sim.stop()
                    relay.close()
                    gcs.close()
                }
            }
        }
    }
})
