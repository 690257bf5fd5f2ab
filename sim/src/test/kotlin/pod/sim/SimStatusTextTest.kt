package pod.sim

import pod.core.vehicle.Autopilot
import pod.core.vehicle.Severity
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import kotlin.time.TimeSource

/** The simulator sends long texts in chunks, as ArduPilot's GCS::send_textv and PX4's MavlinkStreamStatustext do. */
class SimStatusTextTest : StringSpec({
    val messages = SimMessages(SimVehicleConfig(systemId = 1), TimeSource.Monotonic.markNow())

    "a text that fits is one STATUSTEXT with id 0" {
        val sent = messages.statusTexts(Severity.WARNING, "Arm: Accels inconsistent")
        sent shouldHaveSize 1
        sent.single().id() shouldBe 0
        sent.single().text() shouldBe "Arm: Accels inconsistent"
    }

    "a longer text goes in 50-character chunks with one new id, counted from 0, the last one shorter" {
        val line = "Mode change to AUTO RTL failed: No landing sequence found"
        val sent = messages.statusTexts(Severity.WARNING, line)
        sent.map { it.text() } shouldBe listOf(line.take(50), line.drop(50))
        sent.map { it.chunkSeq() } shouldBe listOf(0, 1)
        sent.map { it.id() }.distinct().single().let { it != 0 } shouldBe true
        val next = messages.statusTexts(Severity.WARNING, line)
        (next.first().id() != sent.first().id()) shouldBe true
    }

    "a text that fills its chunks exactly ends with an empty chunk" {
        val sent = messages.statusTexts(Severity.INFO, "y".repeat(100))
        sent.map { it.text() } shouldBe listOf("y".repeat(50), "y".repeat(50), "")
        sent.map { it.chunkSeq() } shouldBe listOf(0, 1, 2)
    }

    "PX4 numbers every text from id 0, its first chunked one too, and ends a text that fills its chunks without an empty chunk" {
        val px4 = SimMessages(SimVehicleConfig(systemId = 1, autopilot = Autopilot.PX4), TimeSource.Monotonic.markNow())
        val line = "Arming denied: Resolve system health failures first"
        val first = px4.statusTexts(Severity.CRITICAL, line)
        first.map { it.id() } shouldBe listOf(0, 0)
        first.map { it.chunkSeq() } shouldBe listOf(0, 1)
        first.map { it.text() } shouldBe listOf(line.take(50), line.drop(50))
        px4.statusTexts(Severity.INFO, "Armed").map { it.id() to it.chunkSeq() } shouldBe listOf(1 to 0)
        val full = px4.statusTexts(Severity.INFO, "z".repeat(100))
        full.map { it.text() } shouldBe listOf("z".repeat(50), "z".repeat(50))
        full.map { it.id() } shouldBe listOf(2, 2)
    }
})
