package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.Autopilot
import pod.mavlink.MavlinkVehicle
import pod.mavlink.mission.InvalidMission
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionRejected
import pod.mavlink.action.VehicleDisarmed
import pod.mavlink.mission.ArduPilotMissionStorage
import pod.mavlink.mission.MissionHalfWritten
import pod.mavlink.mission.MissionResult
import pod.mavlink.mission.MissionType
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.seconds

/** [count] waypoints in a line north of Porto at 30 m above home, item 0 current. */
internal fun waypoints(count: Int, type: MissionType = MissionType.MISSION): List<MissionItem> = List(count) { i ->
    MissionItem(
        seq = i,
        frame = 3,
        command = when (type) {
            MissionType.MISSION -> 16
            MissionType.FENCE -> 5001
            MissionType.RALLY -> 5100
        },
        current = type == MissionType.MISSION && i == 0,
        param1 = if (type == MissionType.FENCE) count.toFloat() else 0f,
        x = 411_780_460 + 1000 * i,
        y = -85_957_860,
        z = 30f,
        missionType = type,
    )
}

/** Runs [block] in virtual time with a ground station and one simulated vehicle of [autopilot] connected to it. */
private fun withVehicle(autopilot: Autopilot, block: suspend (MavlinkVehicle, SimVehicle) -> Unit) = virtualRun {
    heard(SimVehicleConfig(systemId = 5, autopilot = autopilot)) { vehicle, sim -> withTimeout(60.seconds) { block(vehicle, sim) } }
}

class MissionTransferSpec : StringSpec({

    for (autopilot in listOf(Autopilot.ARDUPILOT, Autopilot.PX4)) {
        "a 300-item mission uploads into a simulated ${autopilot.name} vehicle and downloads back identical" {
            withVehicle(autopilot) { vehicle, sim ->
                val items = waypoints(300)
                val progress = vehicle.mission.uploading(items).toList()
                progress.last().done shouldBe 300
                progress.map { it.done } shouldBe progress.map { it.done }.sorted()
                val back = vehicle.mission.download()
                val expected = if (autopilot == Autopilot.ARDUPILOT) {
                    // ArduPilot keeps home in item 0.
                    listOf(sim.missionServer.home!!.copy(current = true)) + items.drop(1).map { it.copy(current = false) }
                } else {
                    items
                }
                back shouldBe expected
                sim.missionServer.list(MissionType.MISSION).size shouldBe 300
            }
        }
    }

    "fence and rally lists are kept apart from the mission, and clear empties only its own list" {
        withVehicle(Autopilot.ARDUPILOT) { vehicle, sim ->
            vehicle.mission.upload(waypoints(5))
            vehicle.mission.upload(waypoints(4, MissionType.FENCE), MissionType.FENCE)
            vehicle.mission.upload(waypoints(3, MissionType.RALLY), MissionType.RALLY)
            // ArduPilot keeps fence and rally items as points and sends them back with autocontinue 0.
            vehicle.mission.download(MissionType.FENCE) shouldBe waypoints(4, MissionType.FENCE).map { it.copy(autocontinue = false) }
            vehicle.mission.download(MissionType.RALLY) shouldBe waypoints(3, MissionType.RALLY).map { it.copy(autocontinue = false) }
            vehicle.mission.clear(MissionType.FENCE)
            vehicle.mission.download(MissionType.FENCE).shouldBeEmpty()
            vehicle.mission.download(MissionType.RALLY).size shouldBe 3
            vehicle.mission.download().size shouldBe 5
            sim.missionServer.list(MissionType.FENCE).shouldBeEmpty()
        }
    }

    "a partial write replaces items 3..5 of an ArduPilot vehicle's mission and leaves the rest, checked before sending" {
        withVehicle(Autopilot.ARDUPILOT) { vehicle, sim ->
            vehicle.mission.upload(waypoints(10))
            val before = sim.missionServer.list(MissionType.MISSION)
            val patch = waypoints(6).drop(3).map { it.copy(z = 80f) }
            vehicle.mission.uploadPartial(patch)
            val after = sim.missionServer.list(MissionType.MISSION)
            after shouldBe before.take(3) + patch.map { it.copy(current = false) } + before.drop(6)
            vehicle.mission.download().map { it.z } shouldBe after.map { it.z }
            val gap = listOf(patch[0], patch[2])
            shouldThrow<InvalidMission> { vehicle.mission.uploadPartial(gap) }.message!! shouldContain "seq must be 4 (items are numbered from 3 without gaps), was 5"
        }
    }

    "set-current moves the vehicle's current item" {
        withVehicle(Autopilot.PX4) { vehicle, sim ->
            vehicle.mission.upload(waypoints(10))
            vehicle.mission.setCurrent(7)
            sim.missionServer.current shouldBe 7
            vehicle.mission.download().single { it.current }.seq shouldBe 7
        }
    }

    "an item the vehicle refuses fails the upload with its result; ArduPilot keeps the items stored before it, and Pod will not start or resume that half-written mission" {
        withVehicle(Autopilot.ARDUPILOT) { vehicle, sim ->
            vehicle.mission.upload(waypoints(6))
            val before = sim.missionServer.list(MissionType.MISSION)
            // Pod lets NaN params through (many commands use NaN for "unchanged"); this vehicle refuses it in param1.
            val bad = waypoints(8).toMutableList().also { it[4] = it[4].copy(param1 = Float.NaN) }
            val error = shouldThrow<MissionRejected> { vehicle.mission.upload(bad) }
            error.result shouldBe MissionResult.INVALID_PARAM1
            error.seq shouldBe 4
            // ArduPilot stored items 0..3 as they came (item 0 is home): new up to the refused one, old after it.
            val held = sim.missionServer.list(MissionType.MISSION)
            held.drop(1).take(3) shouldBe ArduPilotMissionStorage.stored(bad.subList(1, 4), fixedWing = false)
            held.drop(4) shouldBe before.drop(4)

            shouldThrow<MissionHalfWritten> { vehicle.action.startMission() }.message shouldBe
                "cannot start the mission: the last upload of the mission list did not complete, so the vehicle may hold it half-written " +
                "(ArduPilot stores each item as it arrives); upload it again first"
            shouldThrow<MissionHalfWritten> { vehicle.action.continueMission() }
            vehicle.mission.upload(waypoints(6))
            shouldThrow<VehicleDisarmed> { vehicle.action.startMission() } // the list is whole again: on to the next check
        }
    }

    "a list that cannot be valid is refused before anything is sent, naming the item" {
        withVehicle(Autopilot.PX4) { vehicle, _ ->
            val items = waypoints(5).toMutableList().also { it[3] = it[3].copy(x = 950_000_000) }
            shouldThrow<InvalidMission> { vehicle.mission.upload(items) }.message!! shouldContain "invalid mission item 3: latitude must be in -90..90, was 95.0"
            shouldThrow<InvalidMission> { vehicle.mission.upload(waypoints(3, MissionType.RALLY)) }.message!! shouldContain "belongs to the rally list"
        }
    }
})
