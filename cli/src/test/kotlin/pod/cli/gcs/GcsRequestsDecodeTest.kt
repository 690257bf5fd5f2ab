package pod.cli.gcs

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import pod.cli.queue.ElementJson
import pod.cli.queue.PatternJson
import pod.cli.queue.PointJson
import kotlin.math.PI

/** The commands' and queue's requests as a page sends them: decoded, and their arguments checked before anything is sent. */
class GcsRequestsDecodeTest : StringSpec({

    "a page's vehicle and queue requests decode to their kinds" {
        GcsRequests.decode("""{"op":"vehicle_takeoff","id":3,"sysid":1,"alt_m":20}""") shouldBe VehicleTakeoff(3, 1, 20.0)
        GcsRequests.decode("""{"op":"vehicle_mode","id":4,"sysid":2,"mode":"LAND"}""") shouldBe VehicleMode(4, 2, "LAND")
        GcsRequests.decode("""{"op":"vehicle_goto","id":5,"sysid":1,"lat":47.1,"lon":8.5,"alt_m":12}""") shouldBe VehicleGoto(5, 1, 47.1, 8.5, 12.0)
        val insert = GcsRequests.decode(
            """{"op":"queue_insert","id":6,"sysid":1,"mode":"append","element":{"pattern":{"type":"circle","center":{"type":"global","lat":47.1,"lon":8.5},"radius":-30},"alt_m":25},"turns":2}""",
        )
        insert.shouldBeInstanceOf<QueueInsert>()
        insert.element.pattern shouldBe PatternJson.Circle(PointJson.Global(47.1, 8.5), -30.0)
        insert.turns shouldBe 2.0
    }

    "a circle's turns become its duration at the queue's circling speed (5 m/s): 2 turns of 30 m last 2·2π·30/5 s" {
        val circle = ElementJson(PatternJson.Circle(PointJson.Global(47.1, 8.5), -30.0), altM = 25.0)
        val element = QueueInsert(1, 1, "append", circle, turns = 2.0).withTurns()
        element.durationS!! shouldBe (2 * 2 * PI * 30 / 5 plusOrMinus 1e-9)
        element.altM shouldBe 25.0
    }

    "turns are refused on anything but a circle, beside a duration, or out of range" {
        val goto = ElementJson(PatternJson.Goto(PointJson.Global(47.1, 8.5)))
        shouldThrow<IllegalArgumentException> { QueueInsert(1, 1, "append", goto, turns = 1.0).withTurns() }.message shouldContain "turns are for a circle"
        val timed = ElementJson(PatternJson.Circle(PointJson.Global(47.1, 8.5), 30.0), durationS = 60.0)
        shouldThrow<IllegalArgumentException> { QueueInsert(1, 1, "append", timed, turns = 1.0).withTurns() }.message shouldContain "not both"
        val circle = timed.copy(durationS = null)
        shouldThrow<IllegalArgumentException> { QueueInsert(1, 1, "append", circle, turns = 0.0).withTurns() }.message shouldContain "turns must be in"
    }

    "a request that is not one is refused with what is wrong, naming no vehicle" {
        shouldThrow<GcsRequestException> { GcsRequests.decode("""{"op":"vehicle_takeoff","id":3,"sysid":1}""") }.message shouldContain "not a request"
        shouldThrow<GcsRequestException> { GcsRequests.decode("""{"op":"vehicle_fly_to_the_moon","id":3,"sysid":1}""") }.message shouldContain "not a request"
    }
})
