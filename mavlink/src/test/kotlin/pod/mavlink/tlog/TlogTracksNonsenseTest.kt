package pod.mavlink.tlog

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.HomePosition
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.codec.FrameEncoder
import java.io.ByteArrayInputStream
import java.io.ByteArrayOutputStream

/**
 * Found by the tlog fuzz target ([pod.mavlink.fuzz.TlogReading]): a GLOBAL_POSITION_INT or
 * HOME_POSITION that passes its checksum but lies off the globe (latitude 100°) made
 * [TlogTracks.read] throw IllegalArgumentException out of Location's check, losing the whole log.
 */
class TlogTracksNonsenseTest : StringSpec({
    val encoder = FrameEncoder()

    "positions and homes off the globe are skipped; the rest of the log still makes the track" {
        val out = ByteArrayOutputStream()
        TlogWriter(out).use { w ->
            var t = 1_700_000_000_000_000L
            fun add(message: Any) = w.write(t++, encoder.encode(message, 1, 1, 0))
            add(
                Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
                    .baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_ACTIVE).mavlinkVersion(3).build(),
            )
            add(GlobalPositionInt.builder().lat(473977420).lon(85455940).alt(488000).build())
            add(GlobalPositionInt.builder().lat(1_000_000_000).lon(85455940).alt(488000).build()) // 100° N
            add(GlobalPositionInt.builder().lat(473977420).lon(-1_900_000_000).alt(488000).build()) // 190° W
            add(HomePosition.builder().latitude(-1_000_000_000).longitude(0).altitude(0).build())
            add(GlobalPositionInt.builder().lat(473987420).lon(85455940).alt(490000).build())
        }
        val flight = TlogTracks.read(TlogReader(ByteArrayInputStream(out.toByteArray())), stepMetres = 0.0)
        flight.error.shouldBeNull()
        flight.records shouldBe 6
        val track = flight.tracks.single()
        track.points shouldBe listOf(Location(47.397742, 8.545594, 488.0.m), Location(47.398742, 8.545594, 490.0.m))
        track.home.shouldBeNull()
    }
})
