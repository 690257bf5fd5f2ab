package pod.launch.map

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.launch
import pod.core.platform.Platform
import pod.core.platform.PlatformVehicle
import pod.core.units.Location
import java.util.concurrent.ConcurrentHashMap

/** Records where each vehicle of a platform flies: a point whenever it has moved [step] metres. */
internal class Tracks(private val step: Double = 2.0) {
    private val points = ConcurrentHashMap<Int, MutableList<Location>>()
    private val names = ConcurrentHashMap<Int, String>()

    /** Starts recording every vehicle of [platform], present and future, in [scope]. */
    internal fun record(platform: Platform, scope: CoroutineScope): Job = scope.launch {
        val started = mutableSetOf<Int>()
        platform.vehicles.collect { list -> list.filter { started.add(it.id) }.forEach { follow(it, this) } }
    }

    private fun follow(v: PlatformVehicle, scope: CoroutineScope) {
        names[v.id] = v.name
        scope.launch {
            v.position.filterNotNull().collect { p ->
                val track = points.getOrPut(v.id) { mutableListOf() }
                synchronized(track) {
                    if (track.isEmpty() || track.last().distanceTo(p.location).meters >= step) track += p.location
                }
            }
        }
    }

    /** Vehicle id → (name, points so far). */
    internal fun snapshot(): Map<Int, Pair<String, List<Location>>> =
        points.mapValues { (id, track) -> (names[id] ?: "vehicle $id") to synchronized(track) { track.toList() } }
}
