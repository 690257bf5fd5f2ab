package pod.e2e

import com.github.ajalt.clikt.core.parse
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.doubles.shouldBeLessThanOrEqual
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.cli.Pod
import pod.cli.json.Event
import pod.cli.queue.PatternJson
import pod.cli.queue.PointJson
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.net.InetAddress
import java.net.InetSocketAddress
import java.nio.channels.ServerSocketChannel
import java.util.concurrent.atomic.AtomicReference
import kotlin.concurrent.thread
import kotlin.math.abs
import kotlin.math.cos
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * `pod queue serve` flying a simulated ArduCopter's queue, fed by the one-shot `pod queue`
 * commands over its loopback endpoint; every command runs in this JVM, on real loopback sockets.
 */
class QueueCliSpec : StringSpec({

    "serve takes off and flies what append, prepend, next, replace-all and clear send; the copter ends holding in the air" {
        coroutineScope {
            val port = freePort()
            // DISARM_DELAY 0: at 5x a parked copter disarms itself before the takeoff is confirmed.
            val sim = SimVehicle(SimVehicleConfig(systemId = 61, timeScale = 5.0, gcs = "udpout://127.0.0.1:$port", parameters = mapOf("DISARM_DELAY" to 0.0)))
            val served = Captured()
            val ended = AtomicReference<Result<Unit>?>(null)
            var serve: Thread? = null
            try {
                sim.start(this)
                serve = thread(name = "pod-queue-serve") {
                    ended.set(runCatching { Pod(served).parse(listOf("queue", "serve", "--connect", "udpin:127.0.0.1:$port", "--sysid", "61", "--control", "127.0.0.1:0", "--takeoff", "20", "--json")) })
                }

                /** The first event of kind [E] `serve` prints that passes [test]; fails at once with its output if serve ended. */
                suspend fun <E : Event> awaitServed(kind: Class<E>, timeout: Duration, test: (E) -> Boolean = { true }): E = try {
                    withTimeout(timeout) {
                        served.eventFlow.first { e ->
                            ended.get()?.let { throw AssertionError("pod queue serve ended: $it\n${served.lines.joinToString("\n")}") }
                            kind.isInstance(e) && test(kind.cast(e))
                        }.let(kind::cast)
                    }
                } catch (e: kotlinx.coroutines.TimeoutCancellationException) {
                    throw AssertionError("no ${kind.simpleName} from pod queue serve within $timeout (ended: ${ended.get()}):\n${served.lines.joinToString("\n")}", e)
                }

                val control = awaitServed(Event.Listening::class.java, 20.seconds).address
                control.substringBefore(':') shouldBe "127.0.0.1"
                control.substringAfter(':').toInt() shouldBeGreaterThan 0

                /** A client command's one JSON line. */
                suspend fun queue(vararg args: String): Event {
                    val ran = pod("queue", *args, "--control", control, "--json")
                    withClue(ran.text) { ran.code shouldBe 0 }
                    return decodeEvent(ran.afterVersion.single())
                }

                val serving = awaitServed(Event.QueueServing::class.java, 90.seconds)
                serving.sysid shouldBe 61
                serving.control shouldBe control
                serving.relativeAltM!! shouldBeGreaterThan 18.0
                sim.state.value.armed shouldBe true

                // A far goto: it is still flying when the next requests come.
                val goto = queue("append", "goto", "--north", "300", "--east", "0").shouldBeInstanceOf<Event.QueueDone>()
                val gotoEntry = goto.entry.shouldNotBeNull()
                gotoEntry.element.pattern shouldBe PatternJson.Goto(PointJson.Local(300.0, 0.0))
                gotoEntry.element.durationS.shouldBeNull()
                goto.current shouldBe gotoEntry
                goto.pending.shouldBeEmpty()

                val status = queue("status").shouldBeInstanceOf<Event.QueueStatus>()
                status.current shouldBe gotoEntry
                status.remainingS.shouldBeNull()
                status.armed shouldBe true
                // The copter heads north for it.
                withTimeout(30.seconds) { sim.state.first { north(it.location.latitude, it.home.latitude) > 15.0 } }

                val circle = queue("prepend", "circle", "--north", "300", "--east", "0", "--radius", "-30", "--duration", "30").shouldBeInstanceOf<Event.QueueDone>()
                val circleEntry = circle.entry.shouldNotBeNull()
                circleEntry.element.pattern shouldBe PatternJson.Circle(PointJson.Local(300.0, 0.0), -30.0)
                circleEntry.element.durationS shouldBe 30.0
                circle.current shouldBe circleEntry
                circle.pending shouldBe listOf(gotoEntry)
                circle.remainingS!! shouldBeGreaterThan 20.0
                circle.remainingS!! shouldBeLessThanOrEqual 30.0

                val next = queue("next").shouldBeInstanceOf<Event.QueueDone>()
                next.ended shouldBe circleEntry
                next.current shouldBe gotoEntry
                next.pending.shouldBeEmpty()

                // Negative values are numbers, not options; --alt climbs to 25 m on the way.
                val path = queue("replace-all", "path", "--points", "30,-15", "-10,-15", "--alt", "25").shouldBeInstanceOf<Event.QueueDone>()
                val pathEntry = path.entry.shouldNotBeNull()
                pathEntry.element.pattern shouldBe PatternJson.Path(listOf(PointJson.Local(30.0, -15.0), PointJson.Local(-10.0, -15.0)))
                pathEntry.element.altM shouldBe 25.0
                path.current shouldBe pathEntry
                path.pending.shouldBeEmpty()

                // The copter flies the path to its end (the queue says arrived), then holds there.
                awaitServed(Event.QueueEnded::class.java, 60.seconds) { it.entry.id == pathEntry.id }.reason shouldBe "arrived"
                sim.state.value.let {
                    north(it.location.latitude, it.home.latitude) shouldBe (-10.0 plusOrMinus 3.0)
                    east(it.location, it.home) shouldBe (-15.0 plusOrMinus 3.0)
                    it.relativeAltitude.meters shouldBe (25.0 plusOrMinus 2.5)
                }

                val hold = queue("append", "hold").shouldBeInstanceOf<Event.QueueDone>()
                val holdEntry = hold.entry.shouldNotBeNull()
                hold.current shouldBe holdEntry
                val cleared = queue("clear").shouldBeInstanceOf<Event.QueueDone>()
                cleared.current.shouldBeNull()
                cleared.pending.shouldBeEmpty()
                queue("status").shouldBeInstanceOf<Event.QueueStatus>().current.shouldBeNull()

                // Holding in the air: stopped, armed, at the path's height, not sinking.
                val still = withTimeout(30.seconds) { sim.state.first { it.groundSpeed.metersPerSecond < 0.3 && abs(it.climbRate.metersPerSecond) < 0.3 } }
                still.armed shouldBe true
                still.relativeAltitude.meters shouldBe (25.0 plusOrMinus 2.5)

                // Inside the events, a pattern's and a point's kind is `type`, as in the control protocol.
                served.lines.first { "\"queue_started\"" in it } shouldContain "\"pattern\":{\"type\":\"goto\",\"point\":{\"type\":\"local\",\"north\":300.0,\"east\":0.0}}"

                // What serve said, in order: each element started and ended, and why.
                val story = served.events.mapNotNull {
                    when (it) {
                        is Event.QueueStarted -> "started ${it.entry.id}"
                        is Event.QueueEnded -> "ended ${it.entry.id} ${it.reason}"
                        is Event.QueueEmptied -> "emptied"
                        else -> null
                    }
                }
                val (g, c, p, h) = listOf(gotoEntry.id, circleEntry.id, pathEntry.id, holdEntry.id)
                story shouldBe listOf(
                    "started $g", "ended $g preempted", "started $c", "ended $c skipped", "started $g",
                    "ended $g replaced", "started $p", "ended $p arrived", "emptied",
                    "started $h", "ended $h cleared", "emptied",
                )
            } finally {
                serve?.interrupt()
                serve?.join(20_000)
                sim.stop()
            }
            serve?.isAlive shouldBe false
        }
    }

    "SIGTERM stops serve: the copter holds where it is, in BRAKE, and the command says so and exits 130" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 62, timeScale = 5.0, gcs = "udpout://127.0.0.1:$port", parameters = mapOf("DISARM_DELAY" to 0.0)))
            try {
                sim.start(this)
                val control = "127.0.0.1:${freeTcpPort()}"
                // For people this time (its output is a pipe: plain lines).
                val serve = startPod(listOf("queue", "serve", "--connect", "udpin:127.0.0.1:$port", "--sysid", "62", "--control", control, "--takeoff", "15"))
                serve.awaitOut(90.seconds) { it.startsWith("vehicle 62: flying its queue (GUIDED, armed") }
                // A far goto: the copter is on its way when the signal comes.
                pod("queue", "append", "goto", "--north", "500", "--east", "0", "--control", control).code shouldBe 0
                serve.awaitOut(10.seconds) { it == "vehicle 62: flying #1 goto (500 N, 0 E)" }
                withTimeout(30.seconds) { sim.state.first { it.groundSpeed.metersPerSecond > 3.0 } }
                serve.signal("TERM")
                serve.exitCode(30.seconds) shouldBe 130
                serve.out.value shouldContain "interrupted by SIGTERM: vehicle 62 holding in BRAKE (mode BRAKE, armed)"
                serve.err.value.joinToString("\n") shouldContain "pod: SIGTERM: stopping"
                val still = withTimeout(30.seconds) { sim.state.first { it.groundSpeed.metersPerSecond < 0.3 && abs(it.climbRate.metersPerSecond) < 0.3 } }
                still.modeName shouldBe "BRAKE"
                still.armed shouldBe true
                still.relativeAltitude.meters shouldBeGreaterThan 12.0
                // The endpoint went with it.
                pod("queue", "status", "--control", control).code shouldBe 2
            } finally {
                sim.stop()
            }
        }
    }

    "bad elements and addresses exit 2 with the reason, before anything is sent" {
        // A listener nobody answers on: a command that connected would be waiting in its backlog.
        ServerSocketChannel.open().use { listener ->
            listener.bind(InetSocketAddress(InetAddress.getByName("127.0.0.1"), 0))
            listener.configureBlocking(false)
            val control = "127.0.0.1:${listener.socket().localPort}"
            for ((args, message) in listOf(
                listOf("append", "circle", "--north", "0", "--east", "10", "--radius", "0") to "radius must be non-zero (its sign gives the direction)",
                listOf("prepend", "segment", "--from", "10;5", "--to", "0,0") to "'10;5' is not a point: give NORTH,EAST in metres from home",
                listOf("append", "segment", "--from", "10,5,3", "--to", "0,0") to "'10,5,3' is not a point",
                listOf("replace-all", "path") to "a path needs at least one point",
                listOf("append", "goto", "--north", "1e6", "--east", "0") to "a local point must lie within 100.0 km of home",
                listOf("append", "goto", "--north", "10", "--east", "0", "--alt", "-5") to "altitude must be in (0, 10000] m above home",
                listOf("replace", "hold", "--duration", "Infinity") to "duration must be a finite number of seconds",
                // A duration with units is taken as everywhere else: the point is what is refused.
                listOf("append", "goto", "--north", "1e6", "--east", "0", "--duration", "30s") to "a local point must lie within 100.0 km of home",
            )) {
                val ran = pod("queue", *args.toTypedArray(), "--control", control)
                withClue(ran.text) {
                    ran.code shouldBe 2
                    ran.err.single() shouldContain message
                }
            }
            listener.accept().shouldBeNull()
        }
        pod("queue", "serve", "--control", "192.168.1.20:14660").let {
            it.code shouldBe 2
            it.err.single() shouldContain "the control endpoint must be on a loopback address"
        }
        pod("queue", "next", "--control", "example.com:14660").let {
            it.code shouldBe 2
            it.err.single() shouldContain "must be on a loopback address"
        }
    }

    "a client with no host listening says so and exits 2, with an error event under --json" {
        val ran = pod("queue", "status", "--control", "127.0.0.1:${freeTcpPort()}", "--json")
        ran.code shouldBe 2
        ran.err.single() shouldContain "no `pod queue serve` answers on 127.0.0.1:"
        decodeEvent(ran.afterVersion.single()).shouldBeInstanceOf<Event.Error>().message shouldContain "start one with `pod queue serve --connect LINK`"
    }

    "serve refuses a control port already taken, with exit 2, before it looks for a vehicle" {
        ServerSocketChannel.open().use { taken ->
            taken.bind(InetSocketAddress(InetAddress.getByName("127.0.0.1"), 0))
            val ran = pod("queue", "serve", "--connect", "udpin:127.0.0.1:${freePort()}", "--control", "127.0.0.1:${taken.socket().localPort}", "--wait", "30s")
            ran.code shouldBe 2
            ran.err.single() shouldContain "the port is already in use"
        }
    }
})

/** Metres north of [homeLat]. */
private fun north(lat: Double, homeLat: Double): Double = (lat - homeLat) * METRES_PER_DEGREE

/** Metres east of [home]. */
private fun east(location: pod.core.units.Location, home: pod.core.units.Location): Double =
    (location.longitude - home.longitude) * METRES_PER_DEGREE * cos(Math.toRadians(home.latitude))

private const val METRES_PER_DEGREE = 111_195.0

/** A TCP port on loopback that nothing listens on now. */
private fun freeTcpPort(): Int = ServerSocketChannel.open().use {
    it.bind(InetSocketAddress(InetAddress.getByName("127.0.0.1"), 0))
    it.socket().localPort
}

