package pod.sim.autopilot.profile

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeSameInstanceAs
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.telemetry.FlightModes
import pod.sim.SimFlavor
import pod.sim.SimVehicleConfig
import pod.sim.autopilot.SimParameters
import pod.sim.autopilot.SpeedOverrides

/**
 * Each simulated flavour plays one profile, and the profile's own tables agree with what the
 * ground side knows of that firmware: every mode it can fly has a custom_mode number, its boot
 * mode among them, and its parameter table has what its performance reads.
 */
class AutopilotProfileTest : StringSpec({
    val expected = mapOf(
        SimFlavor.ARDUCOPTER to ArduCopterProfile,
        SimFlavor.ARDUPLANE to ArduPlaneProfile,
        SimFlavor.PX4 to Px4MulticopterProfile,
        SimFlavor.PX4_PLANE to Px4FixedWingProfile,
    )

    "each flavour plays its own profile" {
        for ((flavor, profile) in expected) AutopilotProfile.of(flavor.autopilot, flavor.type) shouldBeSameInstanceAs profile
        AutopilotProfile.of(Autopilot.ARDUPILOT, VehicleType.HEXAROTOR) shouldBeSameInstanceAs ArduCopterProfile
    }

    "the modes a profile names are modes the ground side can number" {
        for ((flavor, profile) in expected) {
            val known = FlightModes.names(flavor.autopilot, flavor.type)
            val named = listOfNotNull(profile.bootMode, profile.returnMode, profile.guidedMode, profile.landMode, profile.landStartMode, profile.afterTakeoffMode, profile.missionEndMode)
            named.filter { it !in known } shouldBe emptyList()
            named.forEach { mode -> (profile.behaviour(mode) != null) shouldBe true }
        }
    }

    "performance and the default radii read only parameters the profile's table has" {
        for ((flavor, profile) in expected) {
            val params = SimParameters(profile.parameters(systemId = 1), profile.integersBytewise, profile.refusesOutOfRange)
            (profile.performance(params, SpeedOverrides()).cruise > 0) shouldBe true
            (profile.defaultAcceptanceRadius(params) > 0) shouldBe true
            (profile.defaultTakeoffHeight(params) > 0) shouldBe true
            (profile.returnAltitude(params, 100.0, 150.0).first >= 100.0) shouldBe true
            profile.keepArmedOnGround?.let { (name, _) -> (params.valueOf(name) != null) shouldBe true }
            SimVehicleConfig.defaultStreamRates(flavor.autopilot, flavor.type) shouldBe profile.streamDefaults
        }
    }

    "ArduPilot reports every arming failure after the ack, PX4 only the first before it" {
        val view = object : ArmingView {
            override val positionReady = false
            override val sensorsReady = false
            override val charge = 1.0
            override val params = SimParameters(ArduCopterProfile.parameters(1))
            override val modeName = "STABILIZE"
            override val calibrating = true
            override val fenceArmingProblem: String? = null
            override val hasLandStart = false
        }
        ArduCopterProfile.armingRefusals(view) shouldContainExactly listOf("Arm: Accels inconsistent", "Arm: AHRS: waiting for home", "PreArm: Calibration in progress")
        ArduCopterProfile.textBeforeAck shouldBe false
        val px4 = object : ArmingView by view {
            override val params = SimParameters(Px4MulticopterProfile.parameters(1), integersBytewise = true, refusesOutOfRange = true)
            override val modeName = "AUTO.LOITER"
        }
        Px4MulticopterProfile.armingRefusals(px4) shouldContainExactly listOf("Arming denied: no valid global position estimate")
        Px4MulticopterProfile.textBeforeAck shouldBe true
    }
})
