package pod.sim

import io.dronefleet.mavlink.common.FenceStatus
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.MissionServerFlavor
import pod.sim.autopilot.SimAutopilot
import pod.sim.autopilot.SimOutput
import kotlin.time.TimeSource

/** A fence breach's FENCE_STATUS, as GCS_MAVLINK::send_fence_status (GCS_Fence.cpp) fills it. */
class SimFenceStatusTest : StringSpec({
    "FENCE_STATUS goes on the wire as message 162 with the breach's fields" {
        val ap = SimAutopilot(Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 1, SimVehicleConfig.DEFAULT_HOME, 1.0, MissionServer(MissionServerFlavor.ARDUPILOT))
        val out = SimOutput.FenceStatus(breached = true, count = 3, type = 3, timeMs = 61_250, mitigation = 1)
        val message = SimMessages(SimVehicleConfig(systemId = 1), TimeSource.Monotonic.markNow()).outputs(out, ap.state(), ap.params).single() as FenceStatus
        listOf(message.breachStatus(), message.breachCount(), message.breachType().value(), message.breachMitigation().value()) shouldBe listOf(1, 3, 3, 1)
        message.breachTime() shouldBe 61_250L
        val frame = FrameEncoder().encode(message, 1, 1, 0)
        (frame[7].toInt() and 0xFF) shouldBe 162 // MAVLink 2 message id, low byte
    }
})
