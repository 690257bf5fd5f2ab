package pod.sim

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import java.util.concurrent.ConcurrentHashMap
import pod.core.platform.Platform
import pod.core.platform.QueueCapable
import pod.core.platform.SurveyCapable
import pod.core.time.Timebase
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.link.LinkAddress
import pod.mavlink.MavlinkVehicle
import pod.mavlink.executor.ExecutorTiming
import pod.mavlink.platform.MavlinkPlatform

/** A kind of simulated vehicle: the airframe and autopilot a [SimVehicle] claims to be. */
public enum class SimFlavor(
    /** The airframe. */
    public val type: VehicleType,
    /** The autopilot. */
    public val autopilot: Autopilot,
) {
    /** An ArduPilot Copter quad. */
    ARDUCOPTER(VehicleType.QUADROTOR, Autopilot.ARDUPILOT),

    /** An ArduPilot Plane. */
    ARDUPLANE(VehicleType.FIXED_WING, Autopilot.ARDUPILOT),

    /** A PX4 quad. */
    PX4(VehicleType.QUADROTOR, Autopilot.PX4),

    /** A PX4 fixed-wing. */
    PX4_PLANE(VehicleType.FIXED_WING, Autopilot.PX4),
}

/**
 * A simulated fleet ready to fly: [simulated] vehicles on loopback UDP, a [station] that hears
 * them, and the [platform] the engine drives (time scale of the fleet). [start] returns once every
 * vehicle is heard with a position and a GPS fix, so it can arm (or throws [SimFleetNotReady]
 * naming what it did not hear); [close] stops everything.
 *
 * ```
 * val fleet = SimPlatform.start(scope, List(3) { SimFlavor.ARDUCOPTER }, timeScale = 20.0)
 * engine.run(program, fleet)
 * fleet.close()
 * ```
 */
public class SimPlatform private constructor(
    /** The simulated vehicles, in system-id order. */
    public val simulated: List<SimVehicle>,
    /** The ground station they send to. */
    public val station: GroundStation,
    /** The platform over the station. */
    public val platform: MavlinkPlatform,
) : Platform by platform, QueueCapable by platform, SurveyCapable by platform, AutoCloseable {

    /** The simulated vehicle with [systemId]; throws NoSuchElementException when there is none. */
    public operator fun get(systemId: Int): SimVehicle =
        simulated.firstOrNull { it.config.systemId == systemId } ?: throw NoSuchElementException("no simulated vehicle $systemId")

    /** Stops the vehicles and the station. */
    override fun close() {
        simulated.forEach { it.stop() }
        station.close()
    }

    /** Starts simulated platforms. */
    public companion object {
        /**
         * Starts one vehicle per entry of [flavors] in [scope], system ids from [firstSystemId],
         * parked [spacing] apart on a ring around [home] (its centre free), with a ground station
         * listening on a free loopback port. Waits up to [readyTimeout] until each vehicle is heard
         * with a position and a 3D fix (else [SimFleetNotReady]), then turns off the disarm of a vehicle armed on the ground
         * (at an accelerated [timeScale] it would pass before a heartbeat confirms the arming).
         *
         * The station and the vehicles read [timebase] and open their links with [openLink]: on a
         * test scheduler's timebase and a [pod.mavlink.link.MemoryNetwork] the whole fleet runs in
         * virtual time (pass a [timeScale] of 1 there). [station] configures the ground station
         * (its timebase is replaced by [timebase]). [configure] adjusts each vehicle's configuration
         * before it starts: `{ it.copy(terrain = t, rangefinder = Rangefinder(), objects = o) }` gives
         * every vehicle the same world.
         */
        public suspend fun start(
            scope: CoroutineScope,
            flavors: List<SimFlavor> = List(3) { SimFlavor.ARDUCOPTER },
            timeScale: Double = 10.0,
            home: Location = SimVehicleConfig.DEFAULT_HOME,
            spacing: Distance = 5.m,
            firstSystemId: Int = 1,
            payloads: ((MavlinkVehicle) -> Set<String>)? = null,
            readyTimeout: Duration = 30.seconds,
            timebase: Timebase = Timebase.System,
            openLink: LinkOpener = LinkOpener.Udp,
            station: GroundStationConfig = GroundStationConfig(),
            configure: (SimVehicleConfig) -> SimVehicleConfig = { it },
        ): SimPlatform {
            require(flavors.size in 1..254) { "flavors must name 1..254 vehicles, was ${flavors.size}" }
            require(firstSystemId in 1..254 && firstSystemId + flavors.size - 1 <= 254) { "system ids $firstSystemId..${firstSystemId + flavors.size - 1} must lie within 1..254" }
            require(timeScale > 0 && timeScale <= 1000) { "timeScale must be in (0, 1000], was $timeScale" }
            require(spacing.meters > 0) { "spacing must be > 0, was $spacing" }
            val gcs = GroundStation.open(openLink.open(LinkAddress.parse("udpin://127.0.0.1:0")), scope, station.copy(timebase = timebase))
            val simulated = ArrayList<SimVehicle>()
            try {
                val positions = SimLayout.ring(home, flavors.size, spacing)
                flavors.forEachIndexed { i, flavor ->
                    val sim = SimVehicle(
                        configure(
                            SimVehicleConfig(
                                systemId = firstSystemId + i, type = flavor.type, autopilot = flavor.autopilot, home = positions[i],
                                gcs = "udpout://127.0.0.1:${gcs.link.localPort}", timeScale = timeScale,
                            ),
                        ),
                        timebase = timebase,
                        openLink = openLink,
                    )
                    simulated += sim
                    sim.start(scope)
                }
                // What each vehicle still lacks, so a timeout can say what was not heard.
                val waiting = ConcurrentHashMap(simulated.associate { it.config.systemId to "no heartbeat" })
                withTimeoutOrNull(readyTimeout) {
                    val heard = gcs.vehicles.first { v -> simulated.all { it.config.systemId in v } }
                    coroutineScope {
                        for (sim in simulated) launch { ready(heard.getValue(sim.config.systemId), sim, waiting) }
                    }
                } ?: throw SimFleetNotReady(readyTimeout, waiting.toMap())
                return SimPlatform(simulated, gcs, MavlinkPlatform(gcs, timeScale, ExecutorTiming(), payloads))
            } catch (e: Throwable) {
                simulated.forEach { it.stop() }
                gcs.close()
                throw e
            }
        }

        /**
         * Waits for a position, a fix and home (so the platform offers the vehicle at once), then
         * keeps a vehicle armed on the ground armed (its profile's parameter); [waiting] says what
         * is still missing, and loses the vehicle once it is ready.
         */
        private suspend fun ready(vehicle: MavlinkVehicle, sim: SimVehicle, waiting: MutableMap<Int, String>) {
            val id = sim.config.systemId
            waiting[id] = "no position"
            vehicle.telemetry.position.first { it != null }
            waiting[id] = "no 3D fix"
            vehicle.telemetry.gps.first { it?.has3dFix == true }
            waiting[id] = "no home"
            vehicle.telemetry.home.first { it != null }
            waiting[id] = "keep-armed parameter not written"
            sim.autopilot.profile.keepArmedOnGround?.let { (name, value) -> vehicle.params.write(name, value) }
            waiting.remove(id)
        }
    }
}

/** Where the vehicles of a simulated fleet are parked. */
internal object SimLayout {
    /** [count] points [spacing] apart on a ring around [center] (one vehicle stands [spacing] east of it). */
    fun ring(center: Location, count: Int, spacing: Distance): List<Location> {
        if (count == 1) return listOf(center.offset(0.m, spacing))
        // A ring whose chord between neighbours is the spacing.
        val radius = maxOf(spacing.meters, spacing.meters / (2 * kotlin.math.sin(kotlin.math.PI / count)))
        return List(count) { i ->
            val a = 2 * kotlin.math.PI * i / count
            center.offset((radius * kotlin.math.sin(a)).m, (radius * kotlin.math.cos(a)).m)
        }
    }
}
