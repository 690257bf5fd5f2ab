package pod.launch

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll

class FleetChoiceTest : StringSpec({
    "without properties a program gets four simulated vehicles in real time" {
        FleetChoice.parse(null, null) shouldBe FleetChoice.Sim(4, 1.0)
        FleetChoice.DEFAULT shouldBe FleetChoice.Sim(4, 1.0)
    }

    "sim and connect read back as pod run writes them" {
        checkAll(Arb.int(1..254), Arb.double(0.01, 1000.0, includeNaNs = false)) { count, scale ->
            val choice = FleetChoice.Sim(count, scale)
            val props = choice.toSystemProperties()
            FleetChoice.parse(props[FleetChoice.FLEET_PROPERTY], props[FleetChoice.TIME_SCALE_PROPERTY]) shouldBe choice
        }
        FleetChoice.parse("connect:udpin://0.0.0.0:14550", null) shouldBe FleetChoice.Connect("udpin://0.0.0.0:14550")
        FleetChoice.Connect("tcp://127.0.0.1:5760").toSystemProperties() shouldBe mapOf("pod.fleet" to "connect:tcp://127.0.0.1:5760")
    }

    "a connected fleet takes a time scale too, for a simulator run faster than real time (pod sim --time-scale X)" {
        FleetChoice.parse("connect:udpin://0.0.0.0:14550", "10") shouldBe FleetChoice.Connect("udpin://0.0.0.0:14550", 10.0)
        val choice = FleetChoice.Connect("udpin://0.0.0.0:14550", 10.0)
        val props = choice.toSystemProperties()
        FleetChoice.parse(props[FleetChoice.FLEET_PROPERTY], props[FleetChoice.TIME_SCALE_PROPERTY]) shouldBe choice
    }

    "a time scale alone speeds up the default fleet" {
        FleetChoice.parse(null, "10") shouldBe FleetChoice.Sim(4, 10.0)
    }

    "malformed values name the property and what it takes" {
        shouldThrow<IllegalArgumentException> { FleetChoice.parse("sim:0", null) }.message!! shouldContain "pod.fleet=sim:0"
        shouldThrow<IllegalArgumentException> { FleetChoice.parse("swarm", null) }.message!! shouldContain "sim:N or connect:ADDRESS"
        shouldThrow<IllegalArgumentException> { FleetChoice.parse("connect:", null) }.message!! shouldContain "connection string is missing"
        shouldThrow<IllegalArgumentException> { FleetChoice.parse("sim:2", "fast") }.message!! shouldContain "pod.timeScale"
    }

    "fromSystemProperties reads this JVM's properties" {
        val before = System.getProperty(FleetChoice.FLEET_PROPERTY)
        try {
            System.setProperty(FleetChoice.FLEET_PROPERTY, "sim:7")
            FleetChoice.fromSystemProperties() shouldBe FleetChoice.Sim(7, 1.0)
        } finally {
            if (before == null) System.clearProperty(FleetChoice.FLEET_PROPERTY) else System.setProperty(FleetChoice.FLEET_PROPERTY, before)
        }
    }
})
