package pod.sim

import io.dronefleet.mavlink.ardupilotmega.CameraFeedback
import io.dronefleet.mavlink.ardupilotmega.CameraFeedbackFlags
import io.dronefleet.mavlink.common.CameraImageCaptured
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.MissionServerFlavor
import pod.sim.autopilot.SimAutopilot
import pod.sim.autopilot.SimOutput
import pod.sim.world.SimObject
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * What a photo sends to the ground: ArduPilot 4.7 CAMERA_FEEDBACK only (AP_Camera_Backend::take_picture
 * → prep_mavlink_msg_camera_feedback; SITL sends no CAMERA_IMAGE_CAPTURED), PX4's camera CAMERA_IMAGE_CAPTURED.
 */
class SimPhotoReportTest : StringSpec({
    val home = SimVehicleConfig.DEFAULT_HOME
    val ap = SimAutopilot(Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 1, home, 1.0, MissionServer(MissionServerFlavor.ARDUPILOT))
    val photo = PhotoEvent(0, 12.seconds, home.copy(altitude = home.altitude + 30.m), missionSeq = null)
    fun reports(config: SimVehicleConfig) = SimMessages(config, TimeSource.Monotonic.markNow()).outputs(SimOutput.Photo(photo), ap.state(), ap.params)

    "ArduPilot reports a photo with CAMERA_FEEDBACK alone, its image numbered from 1, where and when it was taken" {
        val feedback = reports(SimVehicleConfig(systemId = 1)).single().shouldBeInstanceOf<CameraFeedback>()
        feedback.imgIdx() shouldBe 1
        feedback.lat() shouldBe Math.round(home.latitude * 1e7).toInt()
        feedback.lng() shouldBe Math.round(home.longitude * 1e7).toInt()
        feedback.altRel() shouldBe 30f
        feedback.timeUsec().toLong() shouldBe 12_000_000L
        feedback.flags().entry() shouldBe CameraFeedbackFlags.CAMERA_FEEDBACK_PHOTO
    }

    "PX4's camera reports it with CAMERA_IMAGE_CAPTURED; an ArduPilot world with objects adds the detections' CAMERA_IMAGE_CAPTURED before the feedback" {
        reports(SimVehicleConfig(systemId = 1, autopilot = Autopilot.PX4)).single().shouldBeInstanceOf<CameraImageCaptured>()
        val objects = SimObject.scatter(seed = 1, count = 3, center = home, radius = 10.m)
        reports(SimVehicleConfig(systemId = 1, objects = objects)).map { it::class } shouldBe listOf(CameraImageCaptured::class, CameraFeedback::class)
    }
})
