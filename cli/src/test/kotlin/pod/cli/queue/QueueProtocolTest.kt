package pod.cli.queue

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.arbitrary.bind
import io.kotest.property.arbitrary.choice
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.enum
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.map
import io.kotest.property.arbitrary.orNull
import io.kotest.property.checkAll
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import pod.core.mission.SurveyDirection
import pod.core.queue.QueueElement
import pod.core.queue.QueuePattern
import pod.core.queue.QueuePoint
import pod.core.units.Location
import pod.core.units.m
import java.net.Socket
import kotlin.time.Duration.Companion.milliseconds

class QueueProtocolTest : StringSpec({

    "any element survives the trip to JSON and back, as a request line, unchanged" {
        checkAll(500, element) { e ->
            val line = QueueProtocol.encode(QueueRequest.Insert(Insertion.PREPEND, e.toJson()))
            withClue(line) {
                line.contains('\n') shouldBe false
                val back = QueueProtocol.decodeRequest(line)
                back shouldBe QueueRequest.Insert(Insertion.PREPEND, e.toJson())
                (back as QueueRequest.Insert).element.toElement() shouldBe e
            }
        }
    }

    "a request written by hand decodes, absent optional fields being none" {
        QueueProtocol.decodeRequest("""{"type":"insert","mode":"replace_all","element":{"pattern":{"type":"path","points":[{"type":"local","north":10,"east":-5}]}}}""") shouldBe
            QueueRequest.Insert(Insertion.REPLACE_ALL, ElementJson(PatternJson.Path(listOf(PointJson.Local(10.0, -5.0)))))
        QueueProtocol.decodeRequest("""{"type":"next"}""") shouldBe QueueRequest.Next
        QueueProtocol.decodeRequest("""{"type":"status","from":"a newer client"}""") shouldBe QueueRequest.Status
    }

    "a bad element in a well-formed request is refused with the core's message" {
        shouldThrow<IllegalArgumentException> { ElementJson(PatternJson.Circle(PointJson.Local(0.0, 0.0), 0.0)).toElement() }.message!! shouldContain "radius must be non-zero"
        shouldThrow<IllegalArgumentException> { ElementJson(PatternJson.Path(emptyList())).toElement() }.message shouldBe "a path needs at least one point"
        shouldThrow<IllegalArgumentException> { ElementJson(PatternJson.Hold, durationS = Double.NaN).toElement() }.message!! shouldContain "duration must be a finite number"
        shouldThrow<IllegalArgumentException> {
            ElementJson(PatternJson.Survey(PointJson.Local(0.0, 0.0), 10.0, 10.0, 2.0, "UPWARDS")).toElement()
        }.message!! shouldContain "survey direction must be one of"
    }

    "only loopback control addresses are taken, and no name is looked up" {
        ControlAddress.parse("127.0.0.1:14661", anyPort = false) shouldBe ControlAddress("127.0.0.1", 14661)
        ControlAddress.parse("localhost:14661", anyPort = false) shouldBe ControlAddress("127.0.0.1", 14661)
        ControlAddress.parse("127.0.1.1:9", anyPort = false) shouldBe ControlAddress("127.0.1.1", 9)
        ControlAddress.parse("[::1]:14661", anyPort = false).let { it shouldBe ControlAddress("::1", 14661); it.toString() shouldBe "[::1]:14661" }
        ControlAddress.parse("14662", anyPort = false) shouldBe ControlAddress("127.0.0.1", 14662)
        ControlAddress.parse("127.0.0.1:0", anyPort = true).port shouldBe 0
        for (bad in listOf("0.0.0.0:14660", "192.168.1.2:14660", "example.com:14660", "[::]:14660", "127.0.0.300:1")) {
            withClue(bad) { shouldThrow<IllegalArgumentException> { ControlAddress.parse(bad, anyPort = false) }.message!! shouldContain "loopback" }
        }
        for (bad in listOf("127.0.0.1:0", "127.0.0.1:65536", "127.0.0.1:", "127.0.0.1:http")) {
            withClue(bad) { shouldThrow<IllegalArgumentException> { ControlAddress.parse(bad, anyPort = false) }.message!! shouldContain "no valid port" }
        }
    }

    "the server answers each line of a connection in order, refuses a line it cannot read and keeps the connection" {
        QueueControlServer.bind(ControlAddress("127.0.0.1", 0)).use { server ->
            coroutineScope {
                val serving = launch { server.serve { request -> QueueResponse(ok = true, error = request.toString()) } }
                val answers = withContext(Dispatchers.IO) {
                    Socket("127.0.0.1", server.address.port).use { socket ->
                        socket.soTimeout = 10_000
                        val writer = socket.getOutputStream().bufferedWriter()
                        writer.write(QueueProtocol.encode(QueueRequest.Next) + "\n" + "not json\n" + QueueProtocol.encode(QueueRequest.Clear) + "\n")
                        writer.flush()
                        val reader = socket.getInputStream().bufferedReader()
                        List(3) { QueueProtocol.decodeResponse(reader.readLine()) }
                    }
                }
                answers[0] shouldBe QueueResponse(ok = true, error = QueueRequest.Next.toString())
                answers[1].ok shouldBe false
                answers[1].error!! shouldContain "not a queue request"
                answers[2] shouldBe QueueResponse(ok = true, error = QueueRequest.Clear.toString())
                // A client of its own, as the commands use it.
                withContext(Dispatchers.IO) { QueueControlClient(server.address).ask(QueueRequest.Status) } shouldBe QueueResponse(ok = true, error = QueueRequest.Status.toString())
                serving.cancelAndJoin()
            }
            // Cancelled, the server has let its port go: nothing answers there any more.
            shouldThrow<NoQueueHost> { QueueControlClient(server.address, connectTimeoutMs = 2_000).ask(QueueRequest.Status) }
        }
    }
}) {
    private companion object {
        val local: Arb<QueuePoint> = Arb.bind(Arb.double(-1e5, 1e5, includeNaNs = false), Arb.double(-1e5, 1e5, includeNaNs = false)) { n, e -> QueuePoint.Local(n.m, e.m) }
        val global: Arb<QueuePoint> = Arb.bind(Arb.double(-90.0, 90.0, includeNaNs = false), Arb.double(-180.0, 180.0, includeNaNs = false)) { la, lo -> QueuePoint.Global(Location(la, lo, 0.m)) }
        val point: Arb<QueuePoint> = Arb.choice(local, global)
        val side = Arb.double(0.5, 20_000.0, includeNaNs = false)

        val pattern: Arb<QueuePattern> = Arb.choice(
            point.map { QueuePattern.Goto(it) },
            Arb.bind(point, Arb.double(0.1, 10_000.0, includeNaNs = false), Arb.int(0..1)) { c, r, s -> QueuePattern.Circle(c, (if (s == 0) r else -r).m) },
            Arb.bind(point, point) { a, b -> QueuePattern.Segment(a, b) },
            Arb.list(point, 1..8).map { QueuePattern.Path(it) },
            Arb.bind(point, side, side, side, Arb.enum<SurveyDirection>()) { s, l, w, sp, d -> QueuePattern.Survey(s, l.m, w.m, sp.m, d) },
            Arb.int(0..2).map { listOf(QueuePattern.Hold, QueuePattern.Land, QueuePattern.ReturnHome)[it] },
        )

        // Durations to the millisecond, as the protocol carries them; none is null (the core's ≤ 0).
        val element: Arb<QueueElement> = Arb.bind(pattern, Arb.long(1L..86_400_000L).orNull(0.3), Arb.double(0.5, 10_000.0, includeNaNs = false).orNull(0.3)) { p, ms, alt ->
            QueueElement(p, ms?.milliseconds, alt?.m)
        }
    }
}
