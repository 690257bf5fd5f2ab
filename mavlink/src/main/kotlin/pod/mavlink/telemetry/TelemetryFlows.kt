package pod.mavlink.telemetry

import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.Speed
import pod.core.vehicle.Attitude
import pod.core.vehicle.Battery
import pod.core.vehicle.LinkQuality
import pod.core.vehicle.Position

// The telemetry values that change with nearly every frame, kept as the numbers the frame carried
// and turned into Pod's value types only when read (see SnapshotStateFlow). Each writer returns
// having allocated nothing; the conversions are the ones VehicleTelemetry always made.

/** GLOBAL_POSITION_INT as last received; null until the first valid one. */
internal class PositionFlow : SnapshotStateFlow<Position?>() {
    private var known = false
    private var lat = 0
    private var lon = 0
    private var alt = 0
    private var relativeAlt = 0
    private var vx = 0
    private var vy = 0
    private var vz = 0
    private var hdg = 0

    /** Takes one report (latitude and longitude in degrees × 10⁷, altitudes in mm, speeds in cm/s, heading in cdeg); false, and ignored, when its latitude or longitude is impossible. */
    fun update(lat: Int, lon: Int, alt: Int, relativeAlt: Int, vx: Int, vy: Int, vz: Int, hdg: Int): Boolean {
        if (lat !in -900_000_000..900_000_000 || lon !in -1_800_000_000..1_800_000_000) return false
        val changed = synchronized(lock) {
            if (known && lat == this.lat && lon == this.lon && alt == this.alt && relativeAlt == this.relativeAlt &&
                vx == this.vx && vy == this.vy && vz == this.vz && hdg == this.hdg
            ) {
                return@synchronized false
            }
            known = true
            this.lat = lat
            this.lon = lon
            this.alt = alt
            this.relativeAlt = relativeAlt
            this.vx = vx
            this.vy = vy
            this.vz = vz
            this.hdg = hdg
            changedLocked()
            true
        }
        if (changed) wake()
        return true
    }

    override fun snapshot(): Position? = if (!known) null else Position(
        location = Location(lat / 1e7, lon / 1e7, Distance(alt / 1000.0)),
        relativeAltitude = Distance(relativeAlt / 1000.0),
        heading = if (hdg == UNKNOWN_U16) null else Angle(hdg / 100.0),
        velocityNorth = Speed(vx / 100.0),
        velocityEast = Speed(vy / 100.0),
        velocityDown = Speed(vz / 100.0),
    )
}

/** ATTITUDE as last received (radians, as on the wire); null until the first. */
internal class AttitudeFlow : SnapshotStateFlow<Attitude?>() {
    private var known = false
    private var roll = 0f
    private var pitch = 0f
    private var yaw = 0f

    fun update(roll: Float, pitch: Float, yaw: Float) {
        val changed = synchronized(lock) {
            // Compared by bits: a NaN that stays NaN is no change, as Float.equals says.
            if (known && roll.toRawBits() == this.roll.toRawBits() && pitch.toRawBits() == this.pitch.toRawBits() && yaw.toRawBits() == this.yaw.toRawBits()) {
                return@synchronized false
            }
            known = true
            this.roll = roll
            this.pitch = pitch
            this.yaw = yaw
            changedLocked()
            true
        }
        if (changed) wake()
    }

    override fun snapshot(): Attitude? = if (!known) null else Attitude(
        roll = Angle(Math.toDegrees(roll.toDouble())),
        pitch = Angle(Math.toDegrees(pitch.toDouble())),
        yaw = Angle(Math.toDegrees(yaw.toDouble())),
    )
}

/** SYS_STATUS's battery fields as last received; null until the first. */
internal class BatteryFlow : SnapshotStateFlow<Battery?>() {
    private var known = false
    private var remaining = 0
    private var voltage = 0

    /** [remaining] in percent (-1: not estimated), [voltage] in mV (65535: unknown). */
    fun update(remaining: Int, voltage: Int) {
        val changed = synchronized(lock) {
            if (known && remaining == this.remaining && voltage == this.voltage) return@synchronized false
            known = true
            this.remaining = remaining
            this.voltage = voltage
            changedLocked()
            true
        }
        if (changed) wake()
    }

    override fun snapshot(): Battery? = if (!known) null else Battery(
        remaining = remaining.takeIf { it in 0..100 }?.let { it / 100.0 },
        voltage = voltage.takeIf { it != UNKNOWN_U16 }?.let { it / 1000.0 },
    )
}

/** Frames received and lost, counted from sequence numbers: changes with every frame. */
internal class LinkQualityFlow : SnapshotStateFlow<LinkQuality>() {
    private var received = 0L
    private var lost = 0L

    fun update(received: Long, lost: Long) {
        synchronized(lock) {
            this.received = received
            this.lost = lost
            changedLocked()
        }
        wake()
    }

    override fun snapshot(): LinkQuality = LinkQuality(received, lost)
}

/** VFR_HUD as last received; null until the first. */
internal class HudFlow : SnapshotStateFlow<Hud?>() {
    private var known = false
    private var airspeed = 0f
    private var groundspeed = 0f
    private var alt = 0f
    private var climb = 0f
    private var heading = 0
    private var throttle = 0

    fun update(airspeed: Float, groundspeed: Float, alt: Float, climb: Float, heading: Int, throttle: Int) {
        val changed = synchronized(lock) {
            if (known && airspeed.toRawBits() == this.airspeed.toRawBits() && groundspeed.toRawBits() == this.groundspeed.toRawBits() &&
                alt.toRawBits() == this.alt.toRawBits() && climb.toRawBits() == this.climb.toRawBits() &&
                heading == this.heading && throttle == this.throttle
            ) {
                return@synchronized false
            }
            known = true
            this.airspeed = airspeed
            this.groundspeed = groundspeed
            this.alt = alt
            this.climb = climb
            this.heading = heading
            this.throttle = throttle
            changedLocked()
            true
        }
        if (changed) wake()
    }

    override fun snapshot(): Hud? = if (!known) null else Hud(
        airspeed = Speed(airspeed.toDouble()),
        groundspeed = Speed(groundspeed.toDouble()),
        altitude = Distance(alt.toDouble()),
        climbRate = Speed(climb.toDouble()),
        heading = Angle(heading.toDouble()),
        throttle = throttle,
    )
}

/** uint16 "unknown" (UINT16_MAX), as MAVLink marks a heading or voltage it does not have. */
private const val UNKNOWN_U16 = 65535
