package pod.mavlink.telemetry

import io.dronefleet.mavlink.common.CameraImageCaptured
import io.dronefleet.mavlink.common.DistanceSensor
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.flow.first
import java.math.BigInteger
import pod.core.units.Location
import io.dronefleet.mavlink.common.MavDistanceSensor
import io.dronefleet.mavlink.common.MavSensorOrientation
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import pod.core.units.m
import pod.mavlink.codec.MessageCodec
import pod.mavlink.codec.MavFrame

private fun reading(cm: Int, orientation: MavSensorOrientation = MavSensorOrientation.MAV_SENSOR_ROTATION_PITCH_270): DistanceSensor =
    DistanceSensor.builder()
        .minDistance(10).maxDistance(4000).currentDistance(cm)
        .type(MavDistanceSensor.MAV_DISTANCE_SENSOR_LASER).id(0).orientation(orientation)
        .build()

class SensorTelemetryTest : StringSpec({
    "a downward DISTANCE_SENSOR sets the height above ground; out of range clears it; other directions are ignored" {
        val telemetry = VehicleTelemetry()
        telemetry.rangefinder.value shouldBe null
        telemetry.onMessage(reading(1234)) shouldBe true
        telemetry.rangefinder.value shouldBe 12.34.m
        // A forward-facing sensor says nothing about the height.
        telemetry.onMessage(reading(250, MavSensorOrientation.MAV_SENSOR_ROTATION_NONE))
        telemetry.rangefinder.value shouldBe 12.34.m
        // ArduPilot's "nothing in range" (max + 1 m) and a reading under the minimum are no height.
        telemetry.onMessage(reading(4100))
        telemetry.rangefinder.value shouldBe null
        telemetry.onMessage(reading(4000))
        telemetry.rangefinder.value shouldBe 40.m
        telemetry.onMessage(reading(5))
        telemetry.rangefinder.value shouldBe null
    }

    "the reading survives Pod's codec both ways, orientation and all" {
        val codec = MessageCodec.Default
        val payload = codec.encodePayload(reading(1777))
        val decoded = codec.decode(MavFrame(version = 2, sequence = 0, systemId = 1, componentId = 1, messageId = 132, payload = payload)) as DistanceSensor
        val telemetry = VehicleTelemetry()
        telemetry.onMessage(decoded)
        telemetry.rangefinder.value shouldBe 17.77.m
    }

    "CAMERA_IMAGE_CAPTURED comes out as a captured image, file_url and all; one with a nonsense position is refused" {
        val telemetry = VehicleTelemetry()
        val seen = async(start = CoroutineStart.UNDISPATCHED) { telemetry.imagesCaptured.first() }
        val message = CameraImageCaptured.builder()
            .timeBootMs(61_000).timeUtc(BigInteger.ZERO).lat(411_780_460).lon(-85_957_860).alt(150_000).relativeAlt(30_000)
            .q(listOf(1f, 0f, 0f, 0f)).imageIndex(4).captureResult(1).fileUrl("pod-sim://photo/4?objects=2,9").build()
        telemetry.onMessage(message) shouldBe true
        seen.await() shouldBe CapturedImage(4, 61_000, Location(41.178046, -8.595786, 150.m), 30.m, true, "pod-sim://photo/4?objects=2,9")
        telemetry.onMessage(CameraImageCaptured.builder().lat(Int.MAX_VALUE).lon(0).build()) shouldBe false
    }
})
