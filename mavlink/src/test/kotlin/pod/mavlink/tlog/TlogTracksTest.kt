package pod.mavlink.tlog

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.HomePosition
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.VehicleType
import pod.mavlink.codec.FrameEncoder
import java.io.ByteArrayInputStream
import java.io.ByteArrayOutputStream
import kotlin.math.roundToInt

class TlogTracksTest : StringSpec({
    val encoder = FrameEncoder()
    val origin = Location(47.397742, 8.545594, 488.0.m)

    fun heartbeat(type: MavType, autopilot: MavAutopilot) = Heartbeat.builder().type(type).autopilot(autopilot)
        .baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_ACTIVE).mavlinkVersion(3).build()

    fun position(at: Location) = GlobalPositionInt.builder()
        .lat((at.latitude * 1e7).roundToInt()).lon((at.longitude * 1e7).roundToInt())
        .alt((at.altitude.meters * 1000).roundToInt()).relativeAlt(0).build()

    class Log {
        val out = ByteArrayOutputStream()
        val writer = TlogWriter(out)
        var t = 1_700_000_000_000_000L
        var seq = 0

        fun add(frame: ByteArray) {
            t += 100_000
            writer.write(t, frame)
        }

        fun bytes(): ByteArray {
            writer.close()
            return out.toByteArray()
        }
    }

    fun Log.from(system: Int, message: Any) = add(encoder.encode(message, system, 1, seq++ and 255))

    "each vehicle's positions in order, thinned to the step, ending at its last position; ground stations and positions without a fix are left out" {
        val log = Log()
        log.from(255, heartbeat(MavType.MAV_TYPE_GCS, MavAutopilot.MAV_AUTOPILOT_INVALID))
        log.from(255, position(origin.offset(500.m, 0.m))) // a GCS that sends positions is still no vehicle
        log.from(3, position(origin)) // before its first heartbeat: not a vehicle yet, as a station has it
        log.from(1, heartbeat(MavType.MAV_TYPE_QUADROTOR, MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA))
        log.from(3, heartbeat(MavType.MAV_TYPE_FIXED_WING, MavAutopilot.MAV_AUTOPILOT_PX4))
        log.from(1, position(Location(0.0, 0.0))) // no fix yet
        val flown = (0..40).map { origin.offset((it * 0.5).m, 0.m, (it * 0.1).m) } // 20 m north in 0.5 m steps
        flown.forEachIndexed { i, p ->
            log.from(1, position(p))
            log.from(3, position(origin.offset(0.m, (i * 3).m)))
        }
        log.from(1, HomePosition.builder().latitude((origin.latitude * 1e7).roundToInt()).longitude((origin.longitude * 1e7).roundToInt()).altitude(488_000).build())
        val flight = TlogTracks.read(TlogReader(ByteArrayInputStream(log.bytes())), stepMetres = 1.99)

        flight.error shouldBe null
        flight.records shouldBe 89L
        flight.tracks.map { it.systemId } shouldBe listOf(1, 3)
        val copter = flight.tracks[0]
        copter.type shouldBe VehicleType.QUADROTOR
        copter.name shouldBe "vehicle 1 (quadrotor)"
        // Every 4th sample is 2 m on; the last (20 m) is one of them.
        copter.points.size shouldBe 11
        copter.points.zipWithNext().forEach { (a, b) -> a.distanceTo(b).meters shouldBe (2.0 plusOrMinus 0.05) }
        copter.points.last().distanceTo(flown.last()).meters shouldBe (0.0 plusOrMinus 0.02)
        copter.points.last().altitude.meters shouldBe (492.0 plusOrMinus 0.001)
        copter.timesMicros shouldBe copter.timesMicros.sorted()
        copter.home!!.distanceTo(origin).meters shouldBe (0.0 plusOrMinus 0.02)
        val plane = flight.tracks[1]
        plane.type shouldBe VehicleType.FIXED_WING
        plane.points.size shouldBe 41 // 3 m apart: every sample kept
        plane.home shouldBe null
    }

    "a track keeps its last position even within the step of the point before" {
        val log = Log()
        log.from(1, heartbeat(MavType.MAV_TYPE_QUADROTOR, MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA))
        listOf(0.0, 5.0, 5.5).forEach { log.from(1, position(origin.offset(it.m, 0.m))) }
        val track = TlogTracks.read(TlogReader(ByteArrayInputStream(log.bytes())), stepMetres = 2.0).tracks.single()
        track.points.size shouldBe 3
        track.points.last().distanceTo(origin.offset(5.5.m, 0.m)).meters shouldBe (0.0 plusOrMinus 0.02)
    }

    "a log cut off inside a record gives the tracks before the cut and says why it stopped" {
        val log = Log()
        log.from(1, heartbeat(MavType.MAV_TYPE_QUADROTOR, MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA))
        (0..9).forEach { log.from(1, position(origin.offset((it * 3).m, 0.m))) }
        val bytes = log.bytes()
        val flight = TlogTracks.read(TlogReader(ByteArrayInputStream(bytes.copyOf(bytes.size - 5))), stepMetres = 1.0)
        flight.error.shouldBeInstanceOf<TlogTruncated>()
        flight.records shouldBe 10L
        flight.tracks.single().points.size shouldBe 9
    }

    "a negative step is refused" {
        shouldThrow<IllegalArgumentException> { TlogTracks.read(TlogReader(ByteArrayInputStream(ByteArray(0))), stepMetres = -1.0) }
    }
})
