package pod.sim.autopilot

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.ints.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.command.CommandResult
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.MissionServerFlavor
import pod.sim.PhotoEvent
import pod.sim.SimDetections
import pod.sim.SimMessages
import pod.sim.SimVehicleConfig
import pod.sim.world.CameraFov
import pod.sim.world.Hill
import pod.sim.world.SimObject
import pod.sim.world.SimWorld
import pod.sim.world.Terrain
import io.dronefleet.mavlink.common.CameraImageCaptured
import kotlin.math.abs
import kotlin.math.atan
import kotlin.math.cos
import kotlin.math.roundToLong
import kotlin.math.sin
import kotlin.time.TimeSource

private val OBJECTS = SimObject.scatter(seed = 7, count = 1000, center = HOME, radius = 150.m)

/**
 * The objects a nadir photo shows, worked out from the photo's record alone: each object's
 * angle off the camera's axis, along and across the heading, against half the field of view.
 */
private fun expectedIn(photo: PhotoEvent, ground: (SimObject) -> Double, fov: CameraFov = CameraFov.DEFAULT): List<SimObject> =
    OBJECTS.filter { obj ->
        val (north, east) = photo.location.northEastTo(obj.location)
        val h = photo.heading.radians
        val forward = north.meters * cos(h) + east.meters * sin(h)
        val right = east.meters * cos(h) - north.meters * sin(h)
        val below = photo.location.altitude.meters - ground(obj)
        below > 0 &&
            Math.toDegrees(atan(abs(forward) / below)) <= fov.vertical.degrees / 2 &&
            Math.toDegrees(atan(abs(right) / below)) <= fov.horizontal.degrees / 2
    }

private fun world(terrain: Terrain?) = SimAutopilot(
    Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 1, HOME, 1.0, MissionServer(MissionServerFlavor.ARDUPILOT),
    readyAfter = 2.0, world = SimWorld(HOME.altitude.meters, terrain, OBJECTS),
)

/** Takes off to [alt] m, flies to [north]/[east] (so it faces that way) and takes one photo there. */
private fun SimAutopilot.photoAt(north: Double, east: Double, alt: Float): PhotoEvent {
    run(2.5)
    mode("GUIDED") shouldBe CommandResult.ACCEPTED
    armCommand() shouldBe CommandResult.ACCEPTED
    command(CommandRequest(22, z = alt)) shouldBe CommandResult.ACCEPTED
    run(15.0)
    val target = HOME.offset(north.m, east.m)
    command(CommandRequest(192, param1 = -1f, x = (target.latitude * 1e7).roundToLong().toDouble(), y = (target.longitude * 1e7).roundToLong().toDouble(), z = alt, frame = 6))
    runUntil(60.0) { it.state().target == null }
    camera.shoot()
    run(0.1)
    return photos.single()
}

class PhotoDetectionTest : StringSpec({
    "a photo over flat ground detects exactly the seeded objects inside its footprint, turned with the heading" {
        val ap = world(null)
        val photo = ap.photoAt(40.0, 30.0, 30f)
        photo.heading.degrees shouldBe (36.87 plusOrMinus 3.0) // it faces the way it flew
        photo.heightAboveGround!!.meters shouldBe (30.0 plusOrMinus 0.3)
        val expected = expectedIn(photo, { HOME.altitude.meters })
        photo.detected shouldBe expected
        expected.size shouldBeGreaterThan 5 // the footprint (~45 × 30 m) holds several of the 1000
        // An axis-aligned footprint would differ: the heading matters.
        expectedIn(photo.copy(heading = pod.core.units.Angle(0.0)), { HOME.altitude.meters }) shouldNotBe expected
    }

    "over a hill the footprint shrinks with the height above the terrain, and objects on the hill's flanks count at their own depth" {
        val terrain = Terrain(HOME, listOf(Hill(40.m, 30.m, 15.m, 12.m)), slopeEast = 0.01)
        val ap = world(terrain)
        val photo = ap.photoAt(40.0, 30.0, 30f)
        photo.heightAboveGround!!.meters shouldBe (30.0 - 15.0 - 0.3 plusOrMinus 0.4) // the hill and the slope below
        val expected = expectedIn(photo, { terrain.elevationAt(it.location).meters })
        photo.detected shouldBe expected
        expected.size shouldBeGreaterThan 0
        expected.size shouldBeLessThan expectedIn(photo, { HOME.altitude.meters }).size // fewer than over flat ground
    }

    "a photo on the ground or with no objects around detects nothing, and its capture message says so" {
        val ap = SimAutopilot(Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 1, HOME, 1.0, MissionServer(MissionServerFlavor.ARDUPILOT))
        ap.camera.shoot()
        ap.run(0.1)
        ap.photos.single().detected.shouldBeEmpty()
        val outputs = ap.drain().filterIsInstance<SimOutput.Photo>()
        // PX4's camera reports it in CAMERA_IMAGE_CAPTURED (ArduPilot's sends CAMERA_FEEDBACK only: SimPhotoReportTest).
        val messages = SimMessages(SimVehicleConfig(systemId = 1, autopilot = Autopilot.PX4), TimeSource.Monotonic.markNow())
        val captured = messages.outputs(outputs.single(), ap.state(), ap.params).single() as CameraImageCaptured
        SimDetections.parse(captured.fileUrl()) shouldBe SimDetections.Detections(0, emptyList())
    }

    "the detections ride in CAMERA_IMAGE_CAPTURED's file_url and read back as the photo's ids" {
        val ap = world(null)
        val photo = ap.photoAt(-20.0, 50.0, 25f)
        val messages = SimMessages(SimVehicleConfig(systemId = 1, objects = OBJECTS), TimeSource.Monotonic.markNow())
        val captured = messages.outputs(SimOutput.Photo(photo), ap.state(), ap.params).filterIsInstance<CameraImageCaptured>().single()
        val read = SimDetections.parse(captured.fileUrl())!!
        read.imageIndex shouldBe photo.index
        read.ids shouldBe photo.detected.map { it.id }.sorted()
        read.leftOff shouldBe 0
    }

    "a list too long for the field is cut, and says how many it left off" {
        val ids = (1000..1100).toList()
        val url = SimDetections.fileUrl(3, ids)
        (url.length <= 205) shouldBe true
        val read = SimDetections.parse(url)!!
        read.ids + ids.drop(read.ids.size) shouldBe ids
        read.leftOff shouldBe ids.size - read.ids.size
        read.leftOff shouldBeGreaterThan 0
        SimDetections.parse("file:///x.jpg") shouldBe null
    }

    "a ground station's camera commands take photos as ArduPilot's AP_Camera does; a vehicle without a camera refuses them" {
        val ap = world(null)
        ap.run(2.5)
        ap.command(CommandRequest(2000, param1 = 0f, param2 = 0f, param3 = 1f)) shouldBe CommandResult.ACCEPTED // one photo
        ap.run(0.1)
        ap.photos.size shouldBe 1
        ap.command(CommandRequest(203, x = 1.0)) shouldBe CommandResult.ACCEPTED // DO_DIGICAM_CONTROL, shoot
        ap.command(CommandRequest(203, x = 0.0)) shouldBe CommandResult.ACCEPTED // no shot asked
        ap.run(0.1)
        ap.photos.size shouldBe 2
        ap.command(CommandRequest(2000, param2 = 1f, param3 = 3f)) shouldBe CommandResult.ACCEPTED // three, a second apart
        ap.run(5.0)
        ap.photos.size shouldBe 5
        ap.command(CommandRequest(2000, param2 = 1f, param3 = 0f)) shouldBe CommandResult.ACCEPTED // until stopped
        ap.run(2.0)
        ap.command(CommandRequest(2001)) shouldBe CommandResult.ACCEPTED
        val stoppedAt = ap.photos.size
        stoppedAt shouldBeGreaterThan 5
        ap.run(3.0)
        ap.photos.size shouldBe stoppedAt
        ap.command(CommandRequest(2000, param1 = -1f, param3 = 1f)) shouldBe CommandResult.UNSUPPORTED

        val blind = SimAutopilot(
            Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 1, HOME, 1.0, MissionServer(MissionServerFlavor.ARDUPILOT),
            world = SimWorld(HOME.altitude.meters, camera = false),
        )
        blind.command(CommandRequest(2000, param3 = 1f)) shouldBe CommandResult.UNSUPPORTED
        blind.run(0.1)
        blind.photos.shouldBeEmpty()
    }
})
