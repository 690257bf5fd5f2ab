package pod.sim

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.MessageIds
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.CommandResult
import pod.mavlink.command.MavCommands
import pod.mavlink.command.VehicleCommand
import pod.mavlink.platform.MavlinkPlatform
import kotlin.time.Duration.Companion.seconds

class SimPayloadSpec : StringSpec({

    "a vehicle carries a camera only once it says so, and a platform offers exactly what it said" {
        coroutineScope {
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this)
            val withCamera = SimVehicle(SimVehicleConfig(systemId = 7, gcs = "udpout://127.0.0.1:${gcs.link.localPort}"))
            val without = SimVehicle(SimVehicleConfig(systemId = 8, camera = false, gcs = "udpout://127.0.0.1:${gcs.link.localPort}"))
            try {
                withCamera.start(this)
                without.start(this)
                val fleet = withTimeout(10.seconds) { gcs.vehicles.first { it.keys.containsAll(setOf(7, 8)) } }
                // The station asked each for CAMERA_INFORMATION when it found them.
                withTimeout(10.seconds) { fleet.getValue(7).payloads.first { "camera" in it } }

                // Asked again, the one without a camera refuses as ArduPilot does with no camera set up;
                // its answer to the station's own request came before, so nothing can still be on the way.
                val refused = shouldThrow<CommandRejected> {
                    fleet.getValue(8).commands.send(VehicleCommand(MavCommands.REQUEST_MESSAGE, param1 = MessageIds.CAMERA_INFORMATION.toFloat()))
                }
                refused.result shouldBe CommandResult.DENIED
                fleet.getValue(8).payloads.value.shouldBeEmpty()

                val platform = MavlinkPlatform(gcs)
                val offered = withTimeout(10.seconds) { platform.vehicles.first { it.size == 2 } }.associateBy { it.id }
                offered.getValue(7).payloads.value shouldBe setOf("camera")
                offered.getValue(8).payloads.value.shouldBeEmpty()
            } finally {
                withCamera.stop()
                without.stop()
                gcs.close()
            }
        }
    }
})
