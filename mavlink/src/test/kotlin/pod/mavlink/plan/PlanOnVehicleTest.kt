package pod.mavlink.plan

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.MavFrames
import pod.mavlink.mission.MissionItem

class PlanOnVehicleTest : StringSpec({
    val home = Location(41.1785, -8.5957, 120.m)
    val takeoff = MissionItem(1, MavFrames.GLOBAL_RELATIVE_ALT, 22, z = 20f)
    val waypoint = MissionItem(2, MavFrames.GLOBAL_RELATIVE_ALT, 16, x = 411790000, y = -85957000, z = 20f)

    "a download keeps what the vehicle tells: its autopilot and airframe, and a yaw ArduPilot does not store as unknown, not north" {
        val homeItem = MissionItem(0, MavFrames.GLOBAL, 16, x = 411785000, y = -85957000, z = 120f)
        val plan = PlanOnVehicle.plan(listOf(homeItem, takeoff, waypoint), emptyList(), emptyList(), Autopilot.ARDUPILOT, VehicleType.QUADROTOR)
        plan.firmwareType shouldBe 3
        plan.vehicleType shouldBe 2
        plan.plannedHome shouldBe PlanPosition(41.1785, -8.5957, 120.0)
        plan.mission.map { it.param4.isNaN() } shouldBe listOf(true, true)
    }

    "an ArduPilot item 0 at 0°, 0° is no home: the vehicle's HOME_POSITION is the planned home, else there is none" {
        val noHome = MissionItem(0, MavFrames.GLOBAL, 16)
        PlanOnVehicle.plan(listOf(noHome, takeoff), emptyList(), emptyList(), Autopilot.ARDUPILOT).plannedHome shouldBe null
        PlanOnVehicle.plan(listOf(noHome, takeoff), emptyList(), emptyList(), Autopilot.ARDUPILOT, home = home).plannedHome shouldBe
            PlanPosition(41.1785, -8.5957, 120.0)
    }

    "PX4 keeps no home in its mission: the planned home is its HOME_POSITION, and its yaws are kept as they come" {
        val items = listOf(takeoff.copy(seq = 0, param4 = 0f), waypoint.copy(seq = 1, param4 = 90f))
        val plan = PlanOnVehicle.plan(items, emptyList(), emptyList(), Autopilot.PX4, VehicleType.FIXED_WING, home)
        plan.plannedHome shouldBe PlanPosition(41.1785, -8.5957, 120.0)
        plan.mission shouldBe items
        (plan.firmwareType to plan.vehicleType) shouldBe (12 to 1)
    }
})
