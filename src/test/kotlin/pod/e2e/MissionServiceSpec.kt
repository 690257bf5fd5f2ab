package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.comparables.shouldBeGreaterThan
import io.kotest.matchers.comparables.shouldBeLessThan
import io.dronefleet.mavlink.common.MissionCount
import kotlinx.coroutines.flow.toList
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.Autopilot
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.VehicleTiming
import pod.mavlink.mission.MissionRejected
import pod.mavlink.mission.MissionResult
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.TransferTiming
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * Runs [block] in virtual time, on a [VirtualFleet] with a ground station and one simulated
 * vehicle configured by [config], its transfers timed by [transfers]; [block] has 40 s of vehicle time.
 */
private fun withSim(
    config: SimVehicleConfig,
    transfers: TransferTiming = TransferTiming(),
    block: suspend VirtualFleet.(MavlinkVehicle, SimVehicle) -> Unit,
) = virtualRun {
    heard(config, GroundStationConfig(vehicleTiming = VehicleTiming(transfers = transfers))) { vehicle, sim -> withTimeout(40.seconds) { block(vehicle, sim) } }
}

/** Starts uploading [count] items and cancels the upload once the vehicle has taken about a tenth of them. */
private suspend fun cancelUploadMidway(vehicle: MavlinkVehicle, count: Int) = coroutineScope {
    val midway = CompletableDeferred<Unit>()
    val upload = launch { vehicle.mission.uploading(waypoints(count)).collect { if (it.done >= count / 10) midway.complete(Unit) } }
    withTimeout(20.seconds) { midway.await() } // vehicle time
    upload.cancel()
    upload.join()
}

/** Mission upload, download and their failures against simulated autopilots, in virtual time: every bound is vehicle time. */
class MissionServiceSpec : StringSpec({

    "a cancelled upload tells a PX4 vehicle, whose next download then succeeds at once" {
        withSim(SimVehicleConfig(systemId = 31, autopilot = Autopilot.PX4)) { vehicle, sim ->
            val before = sim.missionServer.list(MissionType.MISSION)
            cancelUploadMidway(vehicle, 500)
            val mark = timebase.clock.markNow()
            vehicle.mission.download() shouldBe before
            // PX4 keeps a transfer without a cancel for 5 s and answers DENIED meanwhile.
            mark.elapsedNow() shouldBeLessThan 2.seconds
        }
    }

    "a download after a cancelled upload to an ArduPilot vehicle waits until the vehicle lets go of the upload" {
        // ArduPilot ignores the cancelling MISSION_ACK and answers downloads DENIED until its own
        // 8 s upload timeout: Pod waits for it instead of failing.
        withSim(SimVehicleConfig(systemId = 32, autopilot = Autopilot.ARDUPILOT)) { vehicle, sim ->
            cancelUploadMidway(vehicle, 500)
            // What it holds is half-written (ArduPilot stores each item as it arrives); the download shows it all.
            vehicle.mission.download().map { it.copy(current = false) } shouldBe sim.missionServer.list(MissionType.MISSION)
        }
    }

    "a download while an ArduPilot vehicle holds an upload another process abandoned waits, says why, and succeeds" {
        // What an interrupted `pod mission upload` leaves for the next `pod mission download`: a
        // MISSION_COUNT whose items never come (sent raw, so this process's service knows nothing
        // of it). ArduPilot answers DENIED until its 8 s upload timeout (MissionItemProtocol).
        withSim(SimVehicleConfig(systemId = 35, autopilot = Autopilot.ARDUPILOT)) { vehicle, sim ->
            vehicle.send(MissionCount.builder().targetSystem(35).targetComponent(1).count(20).build())
            val mark = timebase.clock.markNow()
            val progress = vehicle.mission.downloading().toList()
            progress.mapNotNull { it.waiting } shouldBe listOf("the vehicle is still holding an unfinished upload") // said once
            progress.last().items shouldBe sim.missionServer.list(MissionType.MISSION)
            mark.elapsedNow() shouldBeGreaterThan 5.seconds // it did wait for the vehicle to let go
        }
    }

    "a refusal that outlasts the wait says what the vehicle is holding" {
        withSim(SimVehicleConfig(systemId = 36, autopilot = Autopilot.ARDUPILOT), TransferTiming(deniedRetry = 2.seconds)) { vehicle, _ ->
            vehicle.send(MissionCount.builder().targetSystem(36).targetComponent(1).count(20).build())
            shouldThrow<MissionRejected> { vehicle.mission.download() }.message shouldBe
                "download of mission rejected by the vehicle: DENIED: the vehicle is still holding an unfinished upload (refused for 2.0 s)"
        }
    }

    "an upload to an ArduPilot vehicle just booted waits for its mission storage instead of failing with NO_SPACE" {
        withSim(SimVehicleConfig(systemId = 33, autopilot = Autopilot.ARDUPILOT, missionStorageReadyAfter = 3.seconds)) { vehicle, sim ->
            val items = waypoints(10)
            vehicle.mission.upload(items)
            sim.missionServer.list(MissionType.MISSION).drop(1) shouldBe items.drop(1).map { it.copy(current = false) }
        }
    }

    "NO_SPACE from a vehicle that is not starting up fails at once" {
        withSim(SimVehicleConfig(systemId = 34, autopilot = Autopilot.ARDUPILOT, missionStorageReadyAfter = 30.seconds), TransferTiming(serviceStartup = Duration.ZERO)) { vehicle, _ ->
            val mark = timebase.clock.markNow()
            shouldThrow<MissionRejected> { vehicle.mission.upload(waypoints(10)) }.result shouldBe MissionResult.NO_SPACE
            mark.elapsedNow() shouldBeLessThan 2.seconds
        }
    }
})
