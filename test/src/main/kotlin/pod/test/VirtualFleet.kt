package pod.test

import kotlinx.coroutines.test.runTest
import pod.core.engine.Program
import pod.launch.simulate
import pod.mavlink.GroundStationConfig
import pod.sim.PhotoEvent
import pod.sim.SimFlavor
import pod.sim.SimPlatform
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import kotlin.time.Duration

/**
 * A seeded simulated fleet that runs programs in virtual time: the real engine, ground station,
 * MAVLink protocols and simulated autopilots, all on one kotlinx-coroutines-test scheduler and one
 * in-memory network whose faults are drawn from [seed]. Vehicle minutes cost milliseconds, no
 * socket is opened, and the same seed gives the same events at the same virtual times.
 * Build one with [virtualFleet]; it is a value, so one fleet can run any number of programs.
 */
public class VirtualFleet internal constructor(
    /** Where the faults (and so the whole run) are drawn from. */
    public val seed: Long,
    /** The vehicles, in system-id order from 1. */
    public val flavors: List<SimFlavor>,
    /** What goes wrong on datagrams towards the ground station. */
    public val up: LinkFaults,
    /** What goes wrong on datagrams towards the vehicles. */
    public val down: LinkFaults,
    /** The ground station's configuration. */
    public val station: GroundStationConfig,
    private val configure: (SimVehicleConfig) -> SimVehicleConfig,
    /** How often each vehicle's position is sampled into its [Track] (virtual time). */
    public val sampleEvery: Duration,
    /** The real-time guard against a hung run (runTest's timeout), not a bound on behaviour. */
    public val timeout: Duration,
) {
    /** This fleet with another [seed]: the same vehicles and faults, other draws. */
    public fun withSeed(seed: Long): VirtualFleet = VirtualFleet(seed, flavors, up, down, station, configure, sampleEvery, timeout)

    /**
     * Runs [program] on a fresh world of this fleet and returns what happened. The program gets
     * the started [SimPlatform] (every vehicle heard, with a position and a fix) and runs as
     * [pod.launch.simulate] runs it; its exceptions come out of here. Each call is a `runTest` of
     * its own, so it blocks until the run ends (typically well under a second of wall time per
     * vehicle minute) and may be called anywhere, inside kotest's `checkAll` included:
     *
     * ```
     * checkAll(3, Arb.linkFaults()) { faults ->
     *     val record = virtualFleet(seed = 7) { copters(1); faults(faults) }.run { hop(pick { count(1) }[0]) }
     *     record.track(1) should landWithin(3.m, of = record.track(1).home)
     * }
     * ```
     */
    public fun <T> run(program: suspend Program.(SimPlatform) -> T): FleetRecord<T> {
        var record: FleetRecord<T>? = null
        runTest(timeout = timeout) {
            val world = VirtualWorld(this, seed, up, down)
            val background = backgroundScope
            var tracks: Map<Int, Track> = emptyMap()
            var photos: Map<Int, List<PhotoEvent>> = emptyMap()
            var duration = Duration.ZERO
            val (result, sim) = simulate(
                flavors, timeScale = 1.0, timebase = world.timebase, openLink = world.openLink,
                station = station, configure = configure,
            ) { fleet ->
                val origin = world.timebase.clock.markNow()
                val sampler = TrackSampler(fleet, origin, sampleEvery)
                val sampling = sampler.start(background)
                try {
                    program(fleet)
                } finally {
                    sampling.cancel()
                    sampler.sample()
                    duration = origin.elapsedNow()
                    tracks = sampler.tracks()
                    photos = fleet.simulated.associate { it.config.systemId to it.photos.value }
                }
            }
            record = FleetRecord(
                seed, result, sim.events, tracks, photos, sim.flights,
                world.counters(towardsStation = true), world.counters(towardsStation = false), duration,
            )
        }
        return checkNotNull(record) { "the run ended without a record" }
    }

    override fun toString(): String = "VirtualFleet(seed $seed, $flavors, up $up, down $down)"
}
