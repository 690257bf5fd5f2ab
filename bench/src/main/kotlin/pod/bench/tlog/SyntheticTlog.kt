package pod.bench.tlog

import io.dronefleet.mavlink.common.Attitude
import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.HomePosition
import io.dronefleet.mavlink.common.SysStatus
import io.dronefleet.mavlink.common.VfrHud
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.tlog.TlogWriter
import java.nio.file.Files
import java.nio.file.Path
import kotlin.math.PI
import kotlin.math.atan
import kotlin.math.atan2
import kotlin.math.cos
import kotlin.math.roundToInt
import kotlin.math.sin
import kotlin.random.Random
import kotlin.time.Duration

/** The last GLOBAL_POSITION_INT of one vehicle, as sent: degrees × 10⁷ and millimetres above mean sea level. */
data class LoggedPosition(val lat: Int, val lon: Int, val alt: Int) {
    /** The position as Pod's readers build it from those fields. */
    fun location(): Location = Location(lat / 1e7, lon / 1e7, (alt / 1000.0).m)
}

/** What [SyntheticTlog.write] put in the log: what every reader must find. */
data class LogContents(
    val records: Long,
    val bytes: Long,
    /** Seconds from the first record to the last. */
    val logSeconds: Double,
    /** GLOBAL_POSITION_INT records per vehicle system id. */
    val positions: Map<Int, Int>,
    /** The last GLOBAL_POSITION_INT per vehicle system id. */
    val last: Map<Int, LoggedPosition>,
    /** Records per message name. */
    val byMessage: Map<String, Int>,
)

/**
 * A seeded, deterministic tlog of copters flying circles as an ArduCopter streams them to a ground
 * station (SR rates: HEARTBEAT and SYS_STATUS 1 Hz, GLOBAL_POSITION_INT and VFR_HUD 4 Hz, ATTITUDE
 * 10 Hz, one HOME_POSITION after boot), and the station's own HEARTBEAT at 1 Hz, in MAVLink 2.
 *
 * Each vehicle's streams start at a random phase; a vehicle's frames are stamped 2–5 ms after it
 * sent them (the link's delay and jitter, never reordering one sender's frames), the station's when
 * sent; records are in stamp order, as a recorder writes them.
 */
object SyntheticTlog {
    /** 2026-11-25T00:00:00Z, in microseconds since the epoch. */
    const val START_MICROS: Long = 1_795_564_800_000_000L

    const val GCS_SYSTEM: Int = 255
    private const val GCS_COMPONENT = 190
    private const val HOME_AMSL = 488.0
    private val ORIGIN = Location(47.397742, 8.545594, HOME_AMSL.m)

    private enum class Kind(val message: String, val periodMicros: Long) {
        HEARTBEAT("HEARTBEAT", 1_000_000),
        SYS_STATUS("SYS_STATUS", 1_000_000),
        GLOBAL_POSITION_INT("GLOBAL_POSITION_INT", 250_000),
        VFR_HUD("VFR_HUD", 250_000),
        ATTITUDE("ATTITUDE", 100_000),
        HOME_POSITION("HOME_POSITION", 0),
        GCS_HEARTBEAT("HEARTBEAT", 1_000_000),
    }

    /** One frame to write: [source] is a vehicle's system id or [GCS_SYSTEM]. */
    private class Event(val stampMicros: Long, val source: Int, val kind: Kind, val sentMicros: Long)

    /** One copter's circle: everything it reports is a function of its time since the log began. */
    private class Flight(random: Random) {
        val centre: Location = ORIGIN.offset(random.nextDouble(-400.0, 400.0).m, random.nextDouble(-400.0, 400.0).m)
        val radius = random.nextDouble(60.0, 250.0)
        val speed = random.nextDouble(4.0, 12.0)
        val turn = if (random.nextBoolean()) 1.0 else -1.0
        val start = random.nextDouble(0.0, 2 * PI)
        val height = random.nextDouble(30.0, 100.0)
        val bootMs = random.nextLong(30_000, 300_000) // the autopilot booted before the log began

        fun angle(t: Double) = start + turn * speed / radius * t
        fun relAlt(t: Double) = height + 5.0 * sin(2 * PI * t / 120.0)
        fun climb(t: Double) = 5.0 * 2 * PI / 120.0 * cos(2 * PI * t / 120.0)
        fun location(t: Double): Location {
            val a = angle(t)
            return centre.offset((radius * cos(a)).m, (radius * sin(a)).m, relAlt(t).m)
        }
        fun north(t: Double) = -turn * speed * sin(angle(t))
        fun east(t: Double) = turn * speed * cos(angle(t))
        fun headingDeg(t: Double) = (Math.toDegrees(atan2(east(t), north(t))) + 360.0) % 360.0
    }

    /** Writes [vehicles] copters' [duration] of telemetry to [path] (replacing it) and returns what is in it. */
    fun write(path: Path, vehicles: Int, duration: Duration, seed: Long): LogContents {
        require(vehicles in 1..250) { "vehicles must be in 1..250, was $vehicles" }
        require(duration.isPositive()) { "duration must be > 0, was $duration" }
        val random = Random(seed)
        val span = duration.inWholeMicroseconds
        val flights = (1..vehicles).associateWith { Flight(Random(random.nextLong())) }
        val events = ArrayList<Event>()
        for (id in 1..vehicles) {
            val phase = random.nextLong(0, 1_000_000)
            val sent = ArrayList<Pair<Long, Kind>>()
            // One scheduler loop sends every stream due; within it HEARTBEAT goes first, so a reader
            // knows the vehicle before its first position.
            val periodic = listOf(Kind.HEARTBEAT, Kind.SYS_STATUS, Kind.GLOBAL_POSITION_INT, Kind.VFR_HUD, Kind.ATTITUDE)
            periodic.forEachIndexed { order, kind ->
                var t = phase + order * 200L
                while (t < span) {
                    sent += t to kind
                    t += kind.periodMicros
                }
            }
            if (phase + 1_500_000 < span) sent += phase + 1_500_000 to Kind.HOME_POSITION
            sent.sortBy { it.first }
            var lastStamp = Long.MIN_VALUE
            for ((t, kind) in sent) {
                val stamp = maxOf(t + 2_000 + random.nextLong(0, 3_000), lastStamp + 1)
                lastStamp = stamp
                events += Event(stamp, id, kind, t)
            }
        }
        var gcs = random.nextLong(0, 1_000_000)
        while (gcs < span) {
            events += Event(gcs, GCS_SYSTEM, Kind.GCS_HEARTBEAT, gcs)
            gcs += Kind.GCS_HEARTBEAT.periodMicros
        }
        events.sortWith(compareBy<Event> { it.stampMicros }.thenBy { it.source })

        val encoder = FrameEncoder()
        val sequence = IntArray(256)
        val positions = HashMap<Int, Int>()
        val last = HashMap<Int, LoggedPosition>()
        val byMessage = sortedMapOf<String, Int>()
        TlogWriter.create(path).use { writer ->
            for (e in events) {
                val message: Any = if (e.source == GCS_SYSTEM) gcsHeartbeat() else {
                    val message = vehicleMessage(flights.getValue(e.source), e.kind, e.sentMicros / 1e6)
                    if (message is GlobalPositionInt) {
                        positions.merge(e.source, 1, Int::plus)
                        last[e.source] = LoggedPosition(message.lat(), message.lon(), message.alt())
                    }
                    message
                }
                val component = if (e.source == GCS_SYSTEM) GCS_COMPONENT else 1
                val frame = encoder.encode(message, e.source, component, sequence[e.source] and 0xFF)
                sequence[e.source]++
                writer.write(START_MICROS + e.stampMicros, frame)
                byMessage.merge(e.kind.message, 1, Int::plus)
            }
        }
        return LogContents(
            records = events.size.toLong(),
            bytes = Files.size(path),
            logSeconds = (events.last().stampMicros - events.first().stampMicros) / 1e6,
            positions = positions.toSortedMap(),
            last = last.toSortedMap(),
            byMessage = byMessage,
        )
    }

    private fun vehicleMessage(f: Flight, kind: Kind, t: Double): Any {
        val bootMs = f.bootMs + (t * 1000).toLong()
        return when (kind) {
            Kind.HEARTBEAT -> Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
                // Armed, guided, stabilised, custom mode AUTO (3), as ArduCopter flying a mission.
                .baseMode(EnumValue.create(217)).customMode(3).systemStatus(MavState.MAV_STATE_ACTIVE).mavlinkVersion(3).build()
            Kind.GLOBAL_POSITION_INT -> {
                val at = f.location(t)
                GlobalPositionInt.builder().timeBootMs(bootMs)
                    .lat((at.latitude * 1e7).roundToInt()).lon((at.longitude * 1e7).roundToInt())
                    .alt((at.altitude.meters * 1000).roundToInt()).relativeAlt((f.relAlt(t) * 1000).roundToInt())
                    .vx((f.north(t) * 100).roundToInt()).vy((f.east(t) * 100).roundToInt()).vz((-f.climb(t) * 100).roundToInt())
                    .hdg((f.headingDeg(t) * 100).roundToInt() % 36_000).build()
            }
            Kind.ATTITUDE -> Attitude.builder().timeBootMs(bootMs)
                .roll((f.turn * atan(f.speed * f.speed / (f.radius * 9.81))).toFloat()).pitch(-0.05f)
                .yaw(Math.toRadians(if (f.headingDeg(t) > 180) f.headingDeg(t) - 360 else f.headingDeg(t)).toFloat())
                .rollspeed(0.001f * sin(t).toFloat()).pitchspeed(0.001f * cos(t).toFloat()).yawspeed((f.turn * f.speed / f.radius).toFloat())
                .build()
            Kind.VFR_HUD -> VfrHud.builder().airspeed((f.speed + 0.3 * sin(t / 7)).toFloat()).groundspeed(f.speed.toFloat())
                .heading(f.headingDeg(t).toInt()).throttle(45 + (5 * sin(t / 11)).toInt())
                .alt((HOME_AMSL + f.relAlt(t)).toFloat()).climb(f.climb(t).toFloat()).build()
            Kind.SYS_STATUS -> {
                val used = t / 3600.0
                SysStatus.builder()
                    // Gyro, accelerometer, magnetometer, baro, GPS, motor outputs, RC, AHRS, battery.
                    .onboardControlSensorsPresent(EnumValue.create(0x1232_E02F)).onboardControlSensorsEnabled(EnumValue.create(0x1232_E02F))
                    .onboardControlSensorsHealth(EnumValue.create(0x1232_E02F)).load(300 + (t.toInt() % 50))
                    .voltageBattery((16_800 - 2_400 * used).toInt()).currentBattery(1_500 + (t.toInt() % 100))
                    .batteryRemaining((100 - 80 * used).toInt().coerceIn(0, 100)).build()
            }
            Kind.HOME_POSITION -> HomePosition.builder().latitude((f.centre.latitude * 1e7).roundToInt())
                .longitude((f.centre.longitude * 1e7).roundToInt()).altitude((HOME_AMSL * 1000).toInt()).build()
            Kind.GCS_HEARTBEAT -> error("not a vehicle message")
        }
    }

    private fun gcsHeartbeat() = Heartbeat.builder().type(MavType.MAV_TYPE_GCS).autopilot(MavAutopilot.MAV_AUTOPILOT_INVALID)
        .baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_ACTIVE).mavlinkVersion(3).build()
}
