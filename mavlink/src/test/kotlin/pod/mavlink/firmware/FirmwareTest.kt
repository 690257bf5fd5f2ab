package pod.mavlink.firmware

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.plan.MissionFlavor
import pod.mavlink.telemetry.ModeRole

class FirmwareTest : StringSpec({

    "a heartbeat's autopilot and airframe pick the profile" {
        Firmware.of(Autopilot.ARDUPILOT, VehicleType.QUADROTOR) shouldBe ArduCopter
        Firmware.of(Autopilot.ARDUPILOT, VehicleType.GROUND_ROVER) shouldBe ArduCopter
        Firmware.of(Autopilot.ARDUPILOT, VehicleType.VTOL) shouldBe ArduPlane
        Firmware.of(Autopilot.PX4, VehicleType.HEXAROTOR) shouldBe Px4Multicopter
        Firmware.of(Autopilot.PX4, VehicleType.FIXED_WING) shouldBe Px4FixedWing
        Firmware.of(Autopilot.GENERIC, VehicleType.FIXED_WING) shouldBe GenericFirmware(fixedWing = true)
        Firmware.of(Autopilot.OTHER, VehicleType.QUADROTOR) shouldBe GenericFirmware(fixedWing = false)
    }

    "the mission flavour and item 0 come from the same profile" {
        for (autopilot in Autopilot.entries) for (type in VehicleType.entries) {
            val firmware = Firmware.of(autopilot, type)
            MissionFlavor.of(autopilot, type) shouldBe firmware.missionFlavor
            firmware.itemZeroIsHome shouldBe (autopilot == Autopilot.ARDUPILOT)
        }
    }

    "hold needs nobody on the sticks, and each firmware arms in its hold mode or leaves it for one it arms in" {
        ArduCopter.modeFor(ModeRole.HOLD) shouldBe "BRAKE"
        ArduCopter.armsIn("BRAKE") shouldBe false
        ArduPlane.modeFor(ModeRole.HOLD) shouldBe "LOITER"
        ArduPlane.armsIn("LOITER") shouldBe true
        ArduPlane.modeFor(ModeRole.LAND) shouldBe null
        Px4Multicopter.modeFor(ModeRole.HOLD) shouldBe "AUTO.LOITER"
        Px4FixedWing.armsIn("AUTO.RTL") shouldBe false
    }

    "an autopilot without a profile keeps the fallbacks Pod used before profiles" {
        val plane = GenericFirmware(fixedWing = true)
        plane.modeFor(ModeRole.HOLD) shouldBe "LOITER"
        plane.takeOffWay shouldBe TakeOffWay.TAKEOFF_MODE
        plane.missionNeedsTakeOff shouldBe false
        plane.numbersEveryStatusText shouldBe false
        GenericFirmware(fixedWing = false).takeOffWay shouldBe TakeOffWay.COMMAND_IN_GUIDED
    }
})
