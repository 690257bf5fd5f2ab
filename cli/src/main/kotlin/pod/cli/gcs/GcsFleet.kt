package pod.cli.gcs

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.launch
import java.util.concurrent.ConcurrentHashMap
import pod.cli.json.Event
import pod.cli.json.toEvent
import pod.cli.json.VehicleText
import pod.core.engine.EngineEvent
import pod.core.vehicle.StatusText
import pod.mavlink.GroundStation
import pod.mavlink.MavlinkVehicle

/**
 * What `pod gcs` shows and acts on: the vehicles of one [station], and the events of the program
 * that flies them when one does (`pod demo --gcs`, `pod run --gcs`: pass them to [programEvent]).
 * Everything here comes from Pod's public API, as an app's would.
 *
 * Pages come and go; the fleet and what was started from a page (a queue being flown, a survey)
 * live in [scope] and outlast them.
 */
public class GcsFleet(
    public val station: GroundStation,
    /** Where work started from a page runs: cancelling it leaves each vehicle holding, as `pod run` does. */
    public val scope: CoroutineScope,
    /** What the page names as its source: `4 simulated vehicles`, `udpin://0.0.0.0:14550`. */
    public val source: String,
    /** Vehicle seconds per real second: durations a page sends count in vehicle time. */
    public val timeScale: Double = 1.0,
    /** The `--tiles` URL template (`https://tile.example/{z}/{x}/{y}.png`), null for the offline grid. */
    public val tiles: String? = null,
) {
    private val history = ArrayDeque<Event>()
    private val followers = LinkedHashSet<(Event) -> Unit>()
    private val texts = ConcurrentHashMap<Int, StatusText>()

    init {
        // A vehicle says a STATUSTEXT once: it is caught here for every page, open or not yet.
        scope.launch {
            val following = HashSet<Int>()
            station.vehicles.collect { vehicles ->
                for ((sysid, v) in vehicles) {
                    if (following.add(sysid)) {
                        launch {
                            v.statusTexts.collect { t ->
                                texts[sysid] = t
                                logEvent(VehicleText(sysid, t.severity.name, t.text))
                            }
                        }
                    }
                }
            }
        }
    }

    private val services = ConcurrentHashMap<kotlin.reflect.KClass<*>, Any>()

    /**
     * The one [T] of this fleet, made by [create] on first use: what a page feature keeps beyond a
     * page (the queues being flown, the surveys), each feature its own class.
     */
    @Suppress("UNCHECKED_CAST")
    public fun <T : Any> service(type: kotlin.reflect.KClass<T>, create: (GcsFleet) -> T): T =
        services.computeIfAbsent(type) { create(this) } as T

    /** The last STATUSTEXT vehicle [sysid] sent, null before its first. */
    public fun lastText(sysid: Int): StatusText? = texts[sysid]

    /** The vehicle with [sysid], or a [GcsRequestException] saying it is not on the link. */
    public fun vehicle(sysid: Int): MavlinkVehicle =
        station.vehicles.value[sysid] ?: throw GcsRequestException("no vehicle $sysid on ${station.link.address}")

    /** Adds a program's event to the log every page shows (the ones `--json` does not print are left out). */
    public fun programEvent(event: EngineEvent) {
        event.toEvent()?.let(::logEvent)
    }

    /** Adds [event] to the log every page shows; the latest [HISTORY] are kept for pages that open later. */
    public fun logEvent(event: Event) {
        synchronized(history) {
            history.addLast(event)
            if (history.size > HISTORY) history.removeFirst()
            followers.forEach { it(event) }
        }
    }

    /**
     * Hands [follower] the log's latest events (oldest first), then every later one as it is
     * logged, none twice and none missed; call the returned function to stop. [follower] runs
     * under the log's lock: it must only hand the event on.
     */
    public fun followLog(follower: (Event) -> Unit): () -> Unit = synchronized(history) {
        history.forEach(follower)
        followers += follower
        return { synchronized(history) { followers -= follower } }
    }

    private companion object {
        const val HISTORY = 500
    }
}
