package pod.sim

import io.dronefleet.mavlink.common.CommandAck
import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.MavCmd
import io.dronefleet.mavlink.common.ParamRequestRead
import io.dronefleet.mavlink.common.ParamValue
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.mapNotNull
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.LandedState
import pod.mavlink.GroundStation
import pod.mavlink.MavlinkVehicle
import kotlin.time.Duration.Companion.seconds

class SimVehicleUdpSpec : StringSpec({

    "over loopback UDP a ground station arms a simulated ArduCopter, commands a take-off and sees it climb" {
        coroutineScope {
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this)
            val sim = SimVehicle(SimVehicleConfig(systemId = 5, gcs = "udpout://127.0.0.1:${gcs.link.localPort}", timeScale = 4.0))
            try {
                sim.start(this)
                val vehicle = withTimeout(10.seconds) { gcs.vehicles.first { 5 in it } }.getValue(5)

                suspend fun command(id: Int, p1: Float = 0f, p2: Float = 0f, p7: Float = 0f): CommandAck {
                    val ack = async(start = CoroutineStart.UNDISPATCHED) {
                        vehicle.messages.mapNotNull { it.message as? CommandAck }.first { it.command().value() == id }
                    }
                    gcs.send(
                        CommandLong.builder().targetSystem(5).targetComponent(1).command(EnumValue.create<MavCmd>(id))
                            .param1(p1).param2(p2).param7(p7).build(),
                    )
                    return withTimeout(5.seconds) { ack.await() }
                }

                // GUIDED needs a position (ArduCopter's "Mode change to GUIDED failed: requires position").
                withTimeout(10.seconds) { vehicle.telemetry.gps.filterNotNull().first { it.has3dFix } }
                command(176, 1f, 4f).result().value() shouldBe 0 // GUIDED
                val arm = command(400, 1f)
                arm.result().value() shouldBe 0
                arm.targetSystem() shouldBe gcs.config.systemId
                withTimeout(10.seconds) { vehicle.telemetry.armed.first { it } }
                command(22, p7 = 10f).result().value() shouldBe 0
                val high = withTimeout(20.seconds) { vehicle.telemetry.position.filterNotNull().first { it.relativeAltitude.meters > 5.0 } }
                high.relativeAltitude.meters shouldBeGreaterThan 5.0
                withTimeout(20.seconds) { vehicle.telemetry.landedState.first { it == LandedState.IN_AIR } }
                sim.state.value.modeName shouldBe "GUIDED"
                readParam(gcs, vehicle, "WPNAV_SPEED") shouldBe 500f
            } finally {
                sim.stop()
                gcs.close()
            }
        }
    }
})

private suspend fun readParam(gcs: GroundStation, vehicle: MavlinkVehicle, name: String): Float = coroutineScope {
    val value = async(start = CoroutineStart.UNDISPATCHED) {
        vehicle.messages.mapNotNull { it.message as? ParamValue }.first { it.paramId() == name }
    }
    gcs.send(ParamRequestRead.builder().targetSystem(vehicle.systemId).targetComponent(1).paramId(name).paramIndex(-1).build())
    withTimeout(5.seconds) { value.await() }.paramValue()
}
