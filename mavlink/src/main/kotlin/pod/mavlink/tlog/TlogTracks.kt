package pod.mavlink.tlog

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.HomePosition
import io.dronefleet.mavlink.minimal.Heartbeat
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.VehicleType
import pod.mavlink.MavlinkEnums
import pod.mavlink.MessageIds
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.MessageCodec
import java.nio.file.Path

/**
 * Where one vehicle flew, as a tlog recorded it: its GLOBAL_POSITION_INT positions in order (a
 * point whenever it had moved at least the reader's step), its last HOME_POSITION, and its type
 * from its heartbeat.
 */
public data class FlownTrack(
    /** The vehicle's MAVLink system id. */
    public val systemId: Int,
    /** What its heartbeat said it is. */
    public val type: VehicleType,
    /** Positions in the order flown, altitudes above mean sea level. */
    public val points: List<Location>,
    /** Microseconds since the epoch of each of [points]. */
    public val timesMicros: List<Long>,
    /** The home it last reported, if it did. */
    public val home: Location? = null,
) {
    /** A name for maps and legends: `vehicle 1 (copter)`. */
    public val name: String get() = "vehicle $systemId (${type.name.lowercase()})"
}

/**
 * Every vehicle's track in a tlog, and whether the log ended early: [error] is the
 * [TlogTruncated] or [TlogCorrupt] that stopped reading (the tracks hold everything before it).
 */
public data class LoggedFlight(
    /** One track per vehicle heard (a vehicle HEARTBEAT sender), by system id. */
    public val tracks: List<FlownTrack>,
    /** Records read. */
    public val records: Long,
    /** Why reading stopped before the end of the file, or null when it was read to the end. */
    public val error: TlogException? = null,
)

/** Reads the flown tracks out of a tlog (see [read]). */
public object TlogTracks {
    /**
     * The tracks of every vehicle in the tlog at [path], a point kept whenever the vehicle has moved
     * [stepMetres] from the last one kept (and always its last position). Frames from ground
     * stations and other non-vehicles are skipped, as a [pod.mavlink.GroundStation] skips them.
     * A file that cannot be opened throws [TlogException]; one cut short or corrupt part way gives
     * what came before, with [LoggedFlight.error] set.
     */
    public fun read(path: Path, stepMetres: Double = 1.0, codec: MessageCodec = MessageCodec.Default): LoggedFlight =
        TlogReader.open(path, codec).use { read(it, stepMetres, codec) }

    /** As [read] for a path, from an open [reader]. */
    public fun read(reader: TlogReader, stepMetres: Double = 1.0, codec: MessageCodec = MessageCodec.Default): LoggedFlight {
        val tracks = TrackRecorder(stepMetres, codec)
        var records = 0L
        val error = try {
            while (true) {
                val record = reader.next() ?: break
                records++
                tracks.onFrame(record.timestampMicros, FrameDirection.RECEIVED, record.frame)
            }
            null
        } catch (e: TlogTruncated) {
            e
        } catch (e: TlogCorrupt) {
            e
        }
        return LoggedFlight(tracks.tracks(), records, error)
    }
}

/**
 * Collects every vehicle's [FlownTrack] from frames as they pass: what [TlogTracks] reads from a
 * file, and what a station shows live when given to [pod.mavlink.GroundStation.record]. A point is
 * kept whenever the vehicle has moved [stepMetres] from the last one kept (and always its last
 * position). Frames from ground stations and other non-vehicles are skipped, as a
 * [pod.mavlink.GroundStation] skips them. Thread-safe.
 */
public class TrackRecorder(
    private val stepMetres: Double = 1.0,
    private val codec: MessageCodec = MessageCodec.Default,
) : FrameTap {
    init {
        require(stepMetres >= 0.0) { "stepMetres must not be negative, was $stepMetres" }
    }

    private val builders = linkedMapOf<Int, Builder>()
    private val decoder = FrameDecoder(codec)

    @Synchronized
    override fun onFrame(timestampMicros: Long, direction: FrameDirection, frame: ByteArray) {
        decoder.feed(frame) { decoded ->
            // Only three messages make a track: the rest (most of a log) is not worth decoding.
            if (decoded.messageId !in TRACK_MESSAGES) return@feed
            when (val message = codec.decode(decoded)) {
                is Heartbeat -> if (MavlinkEnums.isVehicle(message.type().value(), message.autopilot().value())) {
                    builders.getOrPut(decoded.systemId) { Builder() }.type = MavlinkEnums.vehicleType(message.type().value())
                }
                // A frame can pass its checksum and still carry nonsense (a buggy or hostile sender, a
                // corrupt log): a position off the globe is skipped, as VehicleTelemetry skips it live.
                is GlobalPositionInt -> locationOf(message.lat(), message.lon(), message.alt())?.let {
                    builders[decoded.systemId]?.add(it, timestampMicros, stepMetres)
                }
                is HomePosition -> locationOf(message.latitude(), message.longitude(), message.altitude())?.let {
                    builders[decoded.systemId]?.home = it
                }
            }
        }
    }

    private companion object {
        /** The location of degrees × 1e7 and millimetres, or null when it is not on the globe. */
        fun locationOf(latE7: Int, lonE7: Int, altMm: Int): Location? {
            val lat = latE7 / 1e7
            val lon = lonE7 / 1e7
            return if (lat in -90.0..90.0 && lon in -180.0..180.0) Location(lat, lon, (altMm / 1000.0).m) else null
        }

        val TRACK_MESSAGES = setOf(MessageIds.HEARTBEAT, MessageIds.GLOBAL_POSITION_INT, MessageIds.HOME_POSITION)
    }

    /** Every vehicle's track so far, in the order the vehicles were first heard. */
    @Synchronized
    public fun tracks(): List<FlownTrack> = builders.map { (id, b) -> b.build(id) }

    private class Builder {
        var type: VehicleType = VehicleType.OTHER
        var home: Location? = null
        val points = mutableListOf<Location>()
        val times = mutableListOf<Long>()
        var last: Pair<Location, Long>? = null

        fun add(at: Location, micros: Long, step: Double) {
            // A vehicle without a fix sends 0,0: never a point of its track.
            if (at.latitude == 0.0 && at.longitude == 0.0) return
            last = at to micros
            if (points.isEmpty() || points.last().distanceTo(at).meters >= step) {
                points += at
                times += micros
            }
        }

        fun build(id: Int): FlownTrack {
            // The last position heard always ends the track, even within the step of the last point.
            val end = last
            val tail = end != null && points.last() != end.first
            return FlownTrack(
                id, type,
                if (tail) points + end!!.first else points.toList(),
                if (tail) times + end!!.second else times.toList(),
                home,
            )
        }
    }
}
