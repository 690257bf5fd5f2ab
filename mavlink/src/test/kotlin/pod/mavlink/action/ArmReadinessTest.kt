package pod.mavlink.action

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe

class ArmReadinessTest : StringSpec({
    "a booting autopilot's refusals are waited for, naming what it waits for" {
        ArmReadiness.waitFor(listOf("Arm: Accels inconsistent", "Arm: AHRS: waiting for home"), initialising = false) shouldBe
            "Arm: Accels inconsistent; Arm: AHRS: waiting for home"
        ArmReadiness.waitFor(listOf("Arming denied: no valid global position estimate"), initialising = false) shouldBe
            "Arming denied: no valid global position estimate"
    }

    "a refusal waiting cannot clear fails at once, even next to one that would clear" {
        ArmReadiness.waitFor(listOf("PreArm: Battery 1 below minimum arming voltage"), initialising = true) shouldBe null
        ArmReadiness.waitFor(listOf("Arm: AHRS: waiting for home", "PreArm: Battery 1 below minimum arming voltage"), initialising = true) shouldBe null
        ArmReadiness.waitFor(listOf("Arm: RTL mode not armable"), initialising = false) shouldBe null
        ArmReadiness.waitFor(listOf("Arm: DO_LAND_START set and RTL_AUTOLAND disabled"), initialising = false) shouldBe null
        ArmReadiness.waitFor(listOf("Arming denied: low battery"), initialising = true) shouldBe null
    }

    "a refusal without a line is waited for only while the vehicle's own reports say it is booting" {
        ArmReadiness.waitFor(emptyList(), initialising = true) shouldBe "the vehicle to finish initialising"
        ArmReadiness.waitFor(emptyList(), initialising = false) shouldBe null
        ArmReadiness.waitFor(listOf("Something new"), initialising = true) shouldBe null
    }
})
