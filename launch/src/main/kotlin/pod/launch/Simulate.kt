package pod.launch

import kotlinx.coroutines.coroutineScope
import pod.core.engine.Engine
import pod.core.engine.EngineConfig
import pod.core.engine.EngineEvent
import pod.core.engine.Program
import pod.core.mission.Mission
import pod.core.time.Timebase
import pod.launch.geo.MapFeatures
import pod.launch.map.FlightMap
import pod.mavlink.GroundStationConfig
import pod.launch.map.Tracks
import pod.sim.LinkOpener
import pod.sim.SimFlavor
import pod.sim.SimPlatform
import pod.sim.SimVehicleConfig
import java.nio.file.Path

/** What [simulate] saw: every engine event, the missions each vehicle flew, the tracks they flew. */
public class SimRecord(
    /** Every event, in order. */
    public val events: List<EngineEvent>,
    /** (vehicle id, mission) for every flight started. */
    public val flights: List<Pair<Int, Mission>>,
    /** Vehicle id → (name, flown points). */
    public val tracks: Map<Int, Pair<String, List<pod.core.units.Location>>>,
)

/**
 * Runs [program] on a fresh simulated fleet of [flavors] at [timeScale]: prints each event through
 * [onLine] as it happens, writes a map of the planned missions and flown tracks to [map] (if
 * given; SVG, GeoJSON or KML by its extension, see [FlightMap.write]) and returns the program's result with a [SimRecord] of the run. The fleet is stopped
 * afterwards, however the program ends.
 *
 * The engine, the ground station and the vehicles read [timebase] and the fleet's links are opened
 * with [openLink]: given a test scheduler's timebase and a [pod.mavlink.link.MemoryNetwork]
 * (`LinkOpener.memory(network)`) and a [timeScale] of 1, the whole run is in virtual time,
 * deterministic, with no real-time deadline. Call it from a coroutine on [timebase]'s dispatcher.
 * [station] configures the fleet's ground station (a longer `lostAfter` for a lossy link, say).
 * [configure] adjusts each vehicle's configuration before it starts, as in [SimPlatform.start]:
 * `{ it.copy(terrain = hills, rangefinder = Rangefinder(), objects = seeded) }` gives every vehicle
 * the same terrain, a rangefinder and the objects its photos detect; the default changes nothing.
 */
public suspend fun <T> simulate(
    flavors: List<SimFlavor>,
    timeScale: Double,
    onLine: (String) -> Unit = {},
    onEvent: (EngineEvent) -> Unit = {},
    map: Path? = null,
    timebase: Timebase = Timebase.System,
    openLink: LinkOpener = LinkOpener.Udp,
    station: GroundStationConfig = GroundStationConfig(),
    configure: (SimVehicleConfig) -> SimVehicleConfig = { it },
    program: suspend Program.(SimPlatform) -> T,
): Pair<T, SimRecord> = coroutineScope {
    val sim = SimPlatform.start(this, flavors, timeScale, timebase = timebase, openLink = openLink, station = station, configure = configure)
    try {
        val names = sim.platform.vehicles.value.associate { it.id to it.name }
        val events = mutableListOf<EngineEvent>()
        val tracks = Tracks()
        val recording = tracks.record(sim, this)
        try {
            val result = Engine(sim, EngineConfig(timebase = timebase)).runShowing(
                names = { names[it] ?: "vehicle $it" },
                onLine = onLine,
                onEvent = { event ->
                    synchronized(events) { events += event }
                    onEvent(event)
                },
            ) { program(sim) }
            result to SimRecord(synchronized(events) { events.toList() }, flightsOf(events), tracks.snapshot())
        } finally {
            recording.cancel()
            val homes = sim.platform.vehicles.value.mapNotNull { v -> v.home.value?.let { v.id to it } }.toMap()
            if (map != null) flightMap(flightsOf(events), tracks.snapshot(), "Pod on ${flavors.size} simulated vehicles", homes).write(map)
        }
    } finally {
        sim.close()
    }
}

private fun flightsOf(events: List<EngineEvent>): List<Pair<Int, Mission>> =
    synchronized(events) { events.filterIsInstance<EngineEvent.Flying>().map { it.vehicle to it.mission } }

/**
 * The map of [flights] (planned, dashed) and [tracks] (flown, solid, each named at its end by its
 * vehicle), with each vehicle's home from [homes] (vehicle id → home) marked: write it as SVG,
 * GeoJSON or KML.
 */
public fun flightMap(
    flights: List<Pair<Int, Mission>>,
    tracks: Map<Int, Pair<String, List<pod.core.units.Location>>>,
    title: String,
    homes: Map<Int, pod.core.units.Location> = emptyMap(),
): FlightMap {
    val map = FlightMap(title)
    flights.distinctBy { it.first to it.second.name }.forEach { (id, mission) -> map.add(MapFeatures.planned(id, mission)) }
    tracks.forEach { (id, track) -> map.add(MapFeatures.track(id, track.first, track.second)) }
    homes.forEach { (id, at) -> map.add(listOf(MapFeatures.home(id, tracks[id]?.first ?: "vehicle $id", at))) }
    return map
}

/** [flightMap] as an SVG document. */
public fun svg(
    flights: List<Pair<Int, Mission>>,
    tracks: Map<Int, Pair<String, List<pod.core.units.Location>>>,
    title: String,
    homes: Map<Int, pod.core.units.Location> = emptyMap(),
): String = flightMap(flights, tracks, title, homes).svg()
