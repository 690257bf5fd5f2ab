package pod.test

import pod.core.engine.EngineEvent
import pod.core.mission.Mission
import pod.sim.PhotoEvent
import pod.sim.fault.LinkCounters
import kotlin.time.Duration

/**
 * What one run of a program on a [VirtualFleet] did. Times are virtual, on the engine's clock
 * (zero when the program started): [EngineEvent.at], [TrackPoint.at] and the photos' own
 * [PhotoEvent.time] (each vehicle's clock since it booted) are all free of wall time, so two runs
 * of one seed give equal records.
 */
public class FleetRecord<out T>(
    /** The seed the world was built from. */
    public val seed: Long,
    /** What the program returned. */
    public val result: T,
    /** Every engine event, in order, each with its virtual time. */
    public val events: List<EngineEvent>,
    /** Vehicle id → the track it flew. */
    public val tracks: Map<Int, Track>,
    /** Vehicle id → the photos its simulated camera took, in order. */
    public val photos: Map<Int, List<PhotoEvent>>,
    /** (vehicle id, mission) for every mission flight started. */
    public val flights: List<Pair<Int, Mission>>,
    /** What the link's faults did to datagrams towards the ground station. */
    public val towardsStation: LinkCounters,
    /** What the link's faults did to datagrams towards the vehicles. */
    public val towardsVehicles: LinkCounters,
    /** Virtual time from the program's start to its end. */
    public val duration: Duration,
) {
    /** The track of vehicle [id]; fails naming the vehicles there are when it flew none. */
    public fun track(id: Int): Track =
        tracks[id] ?: throw NoSuchElementException("no vehicle $id in this fleet; its vehicles are ${tracks.keys.sorted()}")

    /**
     * The events as comparable lines, each with its virtual time `at` (an error compares by its type and
     * message): equal for two runs of one seed, which is what a determinism test compares.
     */
    public val trace: List<String> get() = events.map { it.toString() }

    override fun toString(): String =
        "FleetRecord(seed $seed, ${events.size} events in $duration, vehicles ${tracks.keys.sorted()}, " +
            "photos ${photos.mapValues { it.value.size }}, towards station $towardsStation, towards vehicles $towardsVehicles)"
}
