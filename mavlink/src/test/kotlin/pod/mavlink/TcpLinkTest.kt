package pod.mavlink

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.VehicleType
import pod.mavlink.codec.FrameEncoder
import java.net.InetAddress
import java.net.ServerSocket
import kotlin.random.Random
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

class TcpLinkTest : StringSpec({

    "a vehicle behind a TCP server is found from frames split at arbitrary byte boundaries, and a hang-up is reported, not thrown from the station's own sends" {
        val uncaught = java.util.concurrent.CopyOnWriteArrayList<Throwable>()
        ServerSocket(0, 1, InetAddress.getByName("127.0.0.1")).use { server ->
            withContext(kotlinx.coroutines.CoroutineExceptionHandler { _, e -> uncaught += e }) {
                val encoder = FrameEncoder()
                val heartbeat = Heartbeat.builder().type(MavType.MAV_TYPE_HEXAROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_PX4)
                    .baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_STANDBY).mavlinkVersion(3).build()
                val position = GlobalPositionInt.builder().lat(-338_688_000).lon(1_512_093_000).alt(40_000).relativeAlt(0).hdg(65535).build()
                val stream = (0 until 20).flatMap { i ->
                    listOf(encoder.encode(heartbeat, 7, 1, 2 * i), encoder.encode(position, 7, 1, 2 * i + 1)).flatMap { it.toList() }
                }.toByteArray()

                val serving = launch(Dispatchers.IO) {
                    server.accept().use { client ->
                        val random = Random(7)
                        var at = 0
                        while (at < stream.size) {
                            val n = minOf(1 + random.nextInt(17), stream.size - at)
                            client.getOutputStream().write(stream, at, n)
                            client.getOutputStream().flush()
                            at += n
                        }
                        // A bound against a station that never hangs up, not a timing assertion.
                        client.soTimeout = 60_000
                        // Keep the connection open until the station has spoken (its heartbeat), then
                        // hang up cleanly: half-close (FIN, which the station reads after the frames
                        // above) and read what it still sends until it closes its side. Closing with
                        // bytes unread makes the kernel reset the connection instead (RST, RFC 2525
                        // 2.17), which the station rightly reports as "broke: Connection reset", not as
                        // a hang-up: on a slow run the station's heartbeats and stream requests pile up
                        // past one read while the frames go out, and the test then timed out (CI).
                        val input = client.getInputStream()
                        input.read()
                        client.shutdownOutput()
                        input.readAllBytes()
                    }
                }
                val gcs = GroundStation.open("tcp:127.0.0.1:${server.localPort}", this, GroundStationConfig(streamRequestInterval = 100.milliseconds, heartbeatInterval = 100.milliseconds))
                try {
                    val vehicle = withTimeout(10.seconds) { gcs.vehicles.first { 7 in it } }.getValue(7)
                    vehicle.identity.value.type shouldBe VehicleType.HEXAROTOR
                    val at = withTimeout(10.seconds) { vehicle.telemetry.position.filterNotNull().first() }.location
                    at.latitude shouldBe -33.8688
                    at.longitude shouldBe 151.2093
                    withTimeout(10.seconds) { vehicle.telemetry.linkQuality.first { it.received == 40L } }.lost shouldBe 0
                    // The station's heartbeat reaches the server, whose read returns; it then hangs up.
                    withContext(Dispatchers.IO) { serving.join() }
                    val error = withTimeout(10.seconds) { gcs.linkError.filterNotNull().first { "closed by the remote" in it.message.orEmpty() } }
                    error.message.shouldNotBeNull() shouldContain "closed by the remote"
                    // The heartbeat and the stream requests keep trying to send on the dead link
                    // (requests every 100 ms here): a second of that must not escape as a failure.
                    kotlinx.coroutines.delay(1.seconds)
                    uncaught shouldBe emptyList()
                } finally {
                    gcs.close()
                }
            }
        }
    }
})
