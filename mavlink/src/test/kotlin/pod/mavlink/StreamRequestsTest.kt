package pod.mavlink

import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.HomePosition
import io.dronefleet.mavlink.common.MavSeverity
import io.dronefleet.mavlink.common.Statustext
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.flow.updateAndGet
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.take
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.runTest
import pod.core.time.Timebase
import pod.core.vehicle.Severity
import pod.mavlink.link.MemoryNetwork
import pod.core.vehicle.StatusText
import pod.mavlink.command.MavCommands
import pod.mavlink.command.ScriptedVehicle

/** A ground station and one scripted vehicle that also sees the station's own requests, in virtual time. */
private fun withScripted(
    config: GroundStationConfig,
    answer: suspend (Any) -> List<Any>,
    block: suspend CoroutineScope.(MavlinkVehicle, ScriptedVehicle) -> Unit,
) = ScriptedVehicle.inVirtualTime(config, seeStationRequests = true, answer = answer, block = block)

private fun CommandLong.asks(command: Int, messageId: Int) = command().value() == command && param1() == messageId.toFloat()

class StreamRequestsTest : StringSpec({

    "the home is asked for at once on discovery, again until it comes, then no more" {
        val asked = AtomicInteger()
        val home = HomePosition.builder().latitude(411780460).longitude(-85957860).altitude(120_000).q(listOf(1f, 0f, 0f, 0f)).build()
        // Like an autopilot whose estimator has no origin yet: no home for the first two requests.
        val config = GroundStationConfig(streamRates = emptyMap(), streamRequestInterval = 200.milliseconds)
        withScripted(config, { m ->
            if (m is CommandLong && m.asks(MavCommands.REQUEST_MESSAGE, 242) && asked.incrementAndGet() >= 3) listOf(home) else emptyList()
        }) { vehicle, _ ->
            withTimeout(5.seconds) { vehicle.telemetry.home.filterNotNull().first() }.latitude shouldBe 41.178046
            asked.get() shouldBe 3
            // Requests stop once the home is known: three more rounds would have come in this time.
            kotlinx.coroutines.delay(600.milliseconds)
            asked.get() shouldBe 3
        }
    }

    "a stream that does not come is asked for again, a bounded number of times; one that came is not" {
        val requests = MutableStateFlow<Map<Int, Int>>(emptyMap())
        val position = GlobalPositionInt.builder().lat(411780460).lon(-85957860).alt(120_000).build()
        val config = GroundStationConfig(
            streamRates = mapOf(33 to 4.0, 1 to 1.0), requestHome = false, requestPayloads = false,
            streamRequestInterval = 150.milliseconds, streamRequestRounds = 4,
        )
        withScripted(config, { m ->
            if (m is CommandLong && m.command().value() == MavCommands.SET_MESSAGE_INTERVAL) {
                val id = m.param1().toInt()
                val n = requests.updateAndGet { it + (id to (it[id] ?: 0) + 1) }.getValue(id)
                // The first request for the position is lost; the second starts it.
                if (id == 33 && n >= 2) listOf(position) else emptyList()
            } else {
                emptyList()
            }
        }) { vehicle, _ ->
            withTimeout(5.seconds) { vehicle.telemetry.position.filterNotNull().first() }
            withTimeout(5.seconds) { requests.first { it[1] == 4 } }
            requests.value[33] shouldBe 2
        }
    }

    "a vehicle found again after being lost is asked for its streams again" {
        val requests = MutableStateFlow(0)
        val config = GroundStationConfig(streamRates = mapOf(33 to 4.0), requestHome = false, requestPayloads = false, lostAfter = 500.milliseconds, streamRequestRounds = 1)
        withScripted(config, { m ->
            if (m is CommandLong && m.asks(MavCommands.SET_MESSAGE_INTERVAL, 33)) requests.update { it + 1 }
            emptyList()
        }) { vehicle, scripted ->
            withTimeout(5.seconds) { requests.first { it >= 1 } }
            scripted.silence()
            withTimeout(5.seconds) { vehicle.connection.first { it == pod.core.vehicle.ConnectionState.LOST } }
            val before = requests.value
            scripted.resume()
            withTimeout(5.seconds) { vehicle.connection.first { it == pod.core.vehicle.ConnectionState.CONNECTED } }
            withTimeout(5.seconds) { requests.first { it > before } }
        }
    }

    "a long STATUSTEXT sent in chunks reaches statusTexts as one line, even with its chunks reordered" {
        val line = "Mode change to AUTO RTL failed: No landing sequence found"
        withScripted(GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false), { emptyList() }) { vehicle, scripted ->
            val texts = async(start = CoroutineStart.UNDISPATCHED) { vehicle.statusTexts.take(2).toList() }
            fun chunk(text: String, seq: Int) = Statustext.builder().severity(MavSeverity.MAV_SEVERITY_WARNING).text(text).id(9).chunkSeq(seq).build()
            scripted.send(chunk(line.substring(50), 1))
            scripted.send(chunk(line.take(50), 0))
            // A second line whose end never comes is delivered as it is, about a second later.
            scripted.send(chunk("x".repeat(50), 0).let { Statustext.builder().severity(it.severity()).text(it.text()).id(10).chunkSeq(0).build() })
            withTimeout(5.seconds) { texts.await() } shouldBe listOf(StatusText(Severity.WARNING, line), StatusText(Severity.WARNING, "x".repeat(50)))
        }
    }
})
