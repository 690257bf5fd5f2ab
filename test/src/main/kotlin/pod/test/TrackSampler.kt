package pod.test

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import pod.core.vehicle.LandedState
import pod.sim.SimPlatform
import kotlin.time.Duration
import kotlin.time.TimeMark

/**
 * Samples where every vehicle of [fleet] physically is, every [every] of virtual time from [origin]
 * (the program's start), into one [Track] per vehicle. Sampling the simulator's state rather than
 * the telemetry makes the tracks what the vehicles did, whatever the lossy link let through.
 */
internal class TrackSampler(private val fleet: SimPlatform, private val origin: TimeMark, private val every: Duration) {
    private val points = fleet.simulated.associate { it.config.systemId to ArrayList<TrackPoint>() }

    /** Starts sampling in [scope] (a scope on the virtual clock); cancel the job to stop. */
    fun start(scope: CoroutineScope): Job = scope.launch {
        while (true) {
            sample()
            delay(every)
        }
    }

    /** Takes one sample of every vehicle now (also the last one, when the program has ended). */
    fun sample() {
        val at = origin.elapsedNow()
        for (sim in fleet.simulated) {
            val state = sim.state.value
            val track = points.getValue(sim.config.systemId)
            synchronized(track) { track += TrackPoint.of(at, state.location, state.home, state.landedState == LandedState.ON_GROUND) }
        }
    }

    /** Vehicle id → its track so far, named as the platform names it. */
    fun tracks(): Map<Int, Track> {
        val names = fleet.platform.vehicles.value.associate { it.id to it.name }
        return fleet.simulated.associate { sim ->
            val id = sim.config.systemId
            val track = points.getValue(id)
            id to Track(id, names[id] ?: "vehicle $id", sim.state.value.home, synchronized(track) { track.toList() })
        }
    }
}
