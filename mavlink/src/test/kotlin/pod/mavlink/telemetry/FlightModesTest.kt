package pod.mavlink.telemetry

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType

class FlightModesTest : StringSpec({

    "ArduPilot and PX4 mode numbers from the autopilots' own tables" {
        listOf(
            Row(Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 3L, "AUTO"),
            Row(Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 4L, "GUIDED"),
            Row(Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 6L, "RTL"),
            Row(Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 9L, "LAND"),
            Row(Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 17L, "BRAKE"),
            Row(Autopilot.ARDUPILOT, VehicleType.FIXED_WING, 10L, "AUTO"),
            Row(Autopilot.ARDUPILOT, VehicleType.FIXED_WING, 11L, "RTL"),
            Row(Autopilot.ARDUPILOT, VehicleType.FIXED_WING, 12L, "LOITER"),
            Row(Autopilot.ARDUPILOT, VehicleType.FIXED_WING, 15L, "GUIDED"),
            Row(Autopilot.PX4, VehicleType.QUADROTOR, (4L shl 16) or (4L shl 24), "AUTO.MISSION"),
            Row(Autopilot.PX4, VehicleType.QUADROTOR, (4L shl 16) or (3L shl 24), "AUTO.LOITER"),
            Row(Autopilot.PX4, VehicleType.QUADROTOR, (4L shl 16) or (5L shl 24), "AUTO.RTL"),
            Row(Autopilot.PX4, VehicleType.QUADROTOR, (4L shl 16) or (6L shl 24), "AUTO.LAND"),
            Row(Autopilot.PX4, VehicleType.QUADROTOR, (4L shl 16) or (2L shl 24), "AUTO.TAKEOFF"),
            Row(Autopilot.PX4, VehicleType.QUADROTOR, 3L shl 16, "POSCTL"),
        ).forEach { (autopilot, type, number, name) ->
            FlightModes.decode(autopilot, type, number).name shouldBe name
            FlightModes.customMode(autopilot, type, name) shouldBe number
        }
    }

    "an unknown number is shown as a number, an unknown name maps to nothing" {
        FlightModes.decode(Autopilot.ARDUPILOT, VehicleType.QUADROTOR, 99).name shouldBe "MODE(99)"
        FlightModes.decode(Autopilot.GENERIC, VehicleType.QUADROTOR, 3).name shouldBe "MODE(3)"
        FlightModes.customMode(Autopilot.ARDUPILOT, VehicleType.FIXED_WING, "ALT_HOLD").shouldBeNull()
        FlightModes.customMode(Autopilot.PX4, VehicleType.QUADROTOR, "POSCTL.MISSION").shouldBeNull()
        FlightModes.customMode(Autopilot.PX4, VehicleType.QUADROTOR, "AUTO.ORBIT").shouldBeNull()
        FlightModes.customMode(Autopilot.PX4, VehicleType.QUADROTOR, "POSCTL.ORBIT.X").shouldBeNull()
    }

    "PX4's orbit (POSCTL main mode 3, sub mode 1) decodes to POSCTL.ORBIT and encodes back; an unknown POSCTL sub mode stays POSCTL" {
        val orbit = (3L shl 16) or (1L shl 24)
        FlightModes.decode(Autopilot.PX4, VehicleType.QUADROTOR, orbit).name shouldBe "POSCTL.ORBIT"
        FlightModes.customMode(Autopilot.PX4, VehicleType.QUADROTOR, "POSCTL.ORBIT") shouldBe orbit
        FlightModes.customMode(Autopilot.PX4, VehicleType.QUADROTOR, "posctl.orbit") shouldBe orbit
        FlightModes.decode(Autopilot.PX4, VehicleType.QUADROTOR, (3L shl 16) or (2L shl 24)).name shouldBe "POSCTL"
        FlightModes.names(Autopilot.PX4, VehicleType.QUADROTOR).contains("POSCTL.ORBIT") shouldBe true
    }

    "every mode role names a mode the autopilot has; hold never names a mode that needs sticks" {
        for (autopilot in listOf(Autopilot.ARDUPILOT, Autopilot.PX4)) {
            for (type in listOf(VehicleType.QUADROTOR, VehicleType.FIXED_WING)) {
                for (role in ModeRole.entries) {
                    val name = FlightModes.forRole(autopilot, type, role)
                    if (autopilot == Autopilot.ARDUPILOT && type == VehicleType.FIXED_WING && role == ModeRole.LAND) {
                        name.shouldBeNull()
                    } else {
                        FlightModes.customMode(autopilot, type, name!!).shouldNotBeNull()
                    }
                }
            }
        }
        FlightModes.forRole(Autopilot.ARDUPILOT, VehicleType.QUADROTOR, ModeRole.HOLD) shouldBe "BRAKE"
        FlightModes.forRole(Autopilot.ARDUPILOT, VehicleType.FIXED_WING, ModeRole.HOLD) shouldBe "LOITER"
        FlightModes.forRole(Autopilot.PX4, VehicleType.QUADROTOR, ModeRole.HOLD) shouldBe "AUTO.LOITER"
        FlightModes.names(Autopilot.PX4, VehicleType.QUADROTOR).contains("AUTO.MISSION") shouldBe true
    }
})

private data class Row<A, B, C, D>(val a: A, val b: B, val c: C, val d: D)
