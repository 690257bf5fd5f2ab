package pod.sim

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.ints.shouldBeGreaterThan
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.delay
import pod.core.time.Timebase
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MessageIds
import pod.mavlink.link.MemoryNetwork
import pod.sim.world.Hill
import pod.sim.world.Rangefinder
import pod.sim.world.SimObject
import pod.sim.world.Terrain
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * A simulated vehicle with a lidar over a hill and objects on the ground, and a ground station, in
 * virtual time on an in-memory network: what reaches `telemetry.rangefinder` and when the autopilot
 * streams it, and how a photo's detections reach the ground.
 */
class SimWorldSpec : StringSpec({
    val home = SimVehicleConfig.DEFAULT_HOME
    // Home sits on a 3 m rise so the vehicle boots on the terrain, not on home's configured altitude.
    val terrain = Terrain(home, listOf(Hill(0.m, 0.m, 3.m, 200.m), Hill(60.m, 0.m, 10.m, 12.m)))

    val objects = SimObject.scatter(seed = 5, count = 600, center = home, radius = 120.m)

    fun world(block: suspend kotlinx.coroutines.CoroutineScope.(GroundStation, SimVehicle) -> Unit, autopilot: Autopilot) = runTest(timeout = 3.minutes) {
        val timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
        val network = MemoryNetwork(backgroundScope, timebase)
        val gcs = GroundStation.open(network.open("udpin://127.0.0.1:0"), backgroundScope, GroundStationConfig(timebase = timebase))
        val sim = SimVehicle(
            SimVehicleConfig(systemId = 3, autopilot = autopilot, gcs = "udpout://127.0.0.1:${gcs.link.localPort}", terrain = terrain, rangefinder = Rangefinder(), objects = objects),
            timebase = timebase, openLink = LinkOpener.memory(network),
        )
        sim.start(backgroundScope)
        try {
            block(gcs, sim)
        } finally {
            sim.stop()
            gcs.close()
        }
    }

    "ArduCopter sends DISTANCE_SENSOR only once asked; then the ground's rangefinder follows the height above the hill" {
        world({ gcs, sim ->
            sim.state.value.location.altitude.meters shouldBe (home.altitude.meters + 3.0 plusOrMinus 1e-3) // booted on the rise
            val vehicle = withTimeout(10.seconds) { gcs.vehicles.first { 3 in it } }.getValue(3)
            vehicle.action.setMode("GUIDED")
            vehicle.action.arm()
            vehicle.action.takeoff(20.m)
            // Flying, but nothing asked, nothing sent: EXTRA3's rate is 0 on ArduCopter.
            delay(3.seconds)
            vehicle.telemetry.rangefinder.value shouldBe null
            (MessageIds.DISTANCE_SENSOR in sim.streamRates.value) shouldBe false
            vehicle.action.setMessageInterval(MessageIds.DISTANCE_SENSOR, 100.milliseconds)
            withTimeout(2.seconds) { vehicle.telemetry.rangefinder.first { it != null } }!!.meters shouldBe (20.0 plusOrMinus 0.6)
            // Over the 10 m hill, level at 20 m above home: the reading dips to ~10 m, as the truth does.
            val homeAltitude = vehicle.telemetry.home.value!!.altitude
            vehicle.action.goto(home.offset(60.m, 0.m).copy(altitude = homeAltitude + 20.m))
            val over = withTimeout(60.seconds) { vehicle.telemetry.rangefinder.first { it != null && it.meters < 10.5 } }!!
            over.meters shouldBe (terrainHeight(sim) plusOrMinus 0.5)
            vehicle.action.awaitArrival(home.offset(60.m, 0.m).copy(altitude = homeAltitude + 20.m), within = 1.m, timeout = 60.seconds)
            delay(1.seconds) // hovering: the latest reading is at most 0.1 s old
            vehicle.telemetry.rangefinder.value!!.meters shouldBe (terrainHeight(sim) plusOrMinus 0.05)
        }, Autopilot.ARDUPILOT)
    }

    "PX4 streams DISTANCE_SENSOR at 0.5 Hz unasked when it has a distance sensor" {
        world({ gcs, sim ->
            sim.streamRates.value[MessageIds.DISTANCE_SENSOR] shouldBe 0.5
            val vehicle = withTimeout(10.seconds) { gcs.vehicles.first { 3 in it } }.getValue(3)
            vehicle.action.arm()
            vehicle.action.takeoff(15.m)
            // Hovering at 15 m: the next reading (every 2 s) is the height there.
            withTimeout(5.seconds) { vehicle.telemetry.rangefinder.first { it != null && it.meters > 14.5 } }!!.meters shouldBe (terrainHeight(sim) plusOrMinus 0.3)
        }, Autopilot.PX4)
    }

    "a photo's detections reach the ground in CAMERA_IMAGE_CAPTURED and read back as the photo's objects" {
        world({ gcs, sim ->
            val vehicle = withTimeout(10.seconds) { gcs.vehicles.first { 3 in it } }.getValue(3)
            vehicle.action.setMode("GUIDED")
            vehicle.action.arm()
            vehicle.action.takeoff(30.m)
            val captured = async(start = CoroutineStart.UNDISPATCHED) { vehicle.telemetry.imagesCaptured.first() }
            sim.autopilot.camera.shoot() // the test runs on the vehicle's (single) thread
            val image = withTimeout(5.seconds) { captured.await() }
            val photo = sim.photos.value.single()
            photo.detected.size shouldBeGreaterThan 3
            image.imageIndex shouldBe photo.index
            image.success shouldBe true
            SimDetections.parse(image.fileUrl) shouldBe SimDetections.Detections(photo.index, photo.detected.map { it.id }.sorted())
        }, Autopilot.ARDUPILOT)
    }

    "a platform's configure hook gives every vehicle the same world: each boots on the terrain, and photos see the same objects" {
        runTest(timeout = 3.minutes) {
            val timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
            val network = MemoryNetwork(backgroundScope, timebase)
            val fleet = SimPlatform.start(
                backgroundScope, List(2) { SimFlavor.ARDUCOPTER }, timeScale = 1.0, spacing = 40.m,
                timebase = timebase, openLink = LinkOpener.memory(network),
            ) { it.copy(terrain = terrain, rangefinder = Rangefinder(), objects = objects) }
            try {
                for (sim in fleet.simulated) {
                    sim.config.objects shouldBe objects
                    sim.state.value.location.altitude.meters shouldBe (terrain.elevationAt(sim.config.home).meters plusOrMinus 1e-9)
                    sim.state.value.home shouldBe sim.state.value.location
                }
            } finally {
                fleet.close()
            }
        }
    }
})

/** The simulator's own truth: the vehicle's height above the terrain below it now. */
private fun terrainHeight(sim: SimVehicle): Double = sim.state.value.heightAboveGround.meters
