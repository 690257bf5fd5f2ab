package pod.mavlink.telemetry

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType

class Px4CustomModeTest : StringSpec({

    "main and sub mode come back out of the number they were packed into" {
        checkAll(Arb.int(0..255), Arb.int(0..255)) { main, sub ->
            val custom = Px4CustomMode.pack(main, sub)
            Px4CustomMode.main(custom) shouldBe main
            Px4CustomMode.sub(custom) shouldBe sub
        }
    }

    "the layout is PX4's: main mode in bits 16..23, sub mode in bits 24..31" {
        Px4CustomMode.pack(4, 4) shouldBe 0x04040000L
        Px4CustomMode.pack(3) shouldBe 0x00030000L
        FlightModes.customMode(Autopilot.PX4, VehicleType.QUADROTOR, "AUTO.LOITER") shouldBe Px4CustomMode.pack(4, 3)
    }
})
