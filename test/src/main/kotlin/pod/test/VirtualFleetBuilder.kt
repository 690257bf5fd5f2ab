package pod.test

import pod.dsl.PodDsl
import pod.mavlink.GroundStationConfig
import pod.sim.SimFlavor
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * A [VirtualFleet] drawn from [seed]: `virtualFleet(seed = 7) { copters(3); plane(1); px4(1); loss(20.percent) }`.
 * Vehicles get system ids from 1 in the order they are added and park on a ring around
 * [SimVehicleConfig.DEFAULT_HOME]; with no vehicle added the fleet is one ArduCopter.
 */
public fun virtualFleet(seed: Long = 1, build: VirtualFleetBuilder.() -> Unit = {}): VirtualFleet =
    VirtualFleetBuilder().apply(build).build(seed)

/** What [virtualFleet] takes; every argument is checked where it is given. */
@PodDsl
public class VirtualFleetBuilder internal constructor() {
    private val flavors = ArrayList<SimFlavor>()
    private var up = LinkFaults.None
    private var down = LinkFaults.None
    private var station: GroundStationConfig? = null
    private var configure: (SimVehicleConfig) -> SimVehicleConfig = { it }

    /** How often each vehicle's position is sampled into its track (virtual time). */
    public var sampleEvery: Duration = 250.milliseconds
        set(value) {
            require(value.isPositive() && value.isFinite()) { "sampleEvery must be > 0 and finite, was $value" }
            field = value
        }

    /** The real-time guard against a hung run (runTest's timeout), not a bound on behaviour. */
    public var timeout: Duration = 3.minutes
        set(value) {
            require(value.isPositive()) { "timeout must be > 0, was $value" }
            field = value
        }

    /** Adds [count] ArduPilot copters. */
    public fun copters(count: Int): Unit = vehicles(SimFlavor.ARDUCOPTER, count)

    /** Adds [count] ArduPilot planes. */
    public fun plane(count: Int = 1): Unit = vehicles(SimFlavor.ARDUPLANE, count)

    /** Adds [count] PX4 copters. */
    public fun px4(count: Int = 1): Unit = vehicles(SimFlavor.PX4, count)

    /** Adds [count] PX4 planes. */
    public fun px4Plane(count: Int = 1): Unit = vehicles(SimFlavor.PX4_PLANE, count)

    /** Adds [count] vehicles of [flavor]. */
    public fun vehicles(flavor: SimFlavor, count: Int) {
        require(count >= 1) { "count must be ≥ 1, was $count" }
        require(flavors.size + count <= MAX_VEHICLES) { "a virtual fleet holds at most $MAX_VEHICLES vehicles, was ${flavors.size + count}" }
        repeat(count) { flavors += flavor }
    }

    /** Loses [share] of the datagrams in each direction, independently (the rest arrive at once, in order). */
    public fun loss(share: Percent) {
        faults(LinkFaults(drop = share.fraction))
    }

    /** What goes wrong on datagrams towards the ground station ([up]) and towards the vehicles ([down]). */
    public fun faults(up: LinkFaults, down: LinkFaults = up) {
        this.up = up
        this.down = down
    }

    /**
     * The ground station's configuration. Left out, it is Pod's default, except that a vehicle is
     * called lost only after 10 s without a heartbeat when the link has faults (heartbeats cross
     * the same lossy link).
     */
    public fun station(config: GroundStationConfig) {
        station = config
    }

    /**
     * Adjusts each vehicle's configuration before it starts (terrain, a rangefinder, objects its
     * camera detects), as `simulate(configure = …)` does; calls compose in order.
     */
    public fun configure(adjust: (SimVehicleConfig) -> SimVehicleConfig) {
        val before = configure
        configure = { adjust(before(it)) }
    }

    internal fun build(seed: Long): VirtualFleet {
        val faulty = !up.isNone || !down.isNone
        val station = station ?: if (faulty) GroundStationConfig(lostAfter = 10.seconds) else GroundStationConfig()
        return VirtualFleet(seed, flavors.ifEmpty { listOf(SimFlavor.ARDUCOPTER) }.toList(), up, down, station, configure, sampleEvery, timeout)
    }

    private companion object {
        /** Virtual time is cheap but not free: a few dozen vehicles is what a test wants. */
        const val MAX_VEHICLES = 64
    }
}
