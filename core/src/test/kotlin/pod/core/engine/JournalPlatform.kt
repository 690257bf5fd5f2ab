package pod.core.engine

import kotlinx.coroutines.flow.flow
import kotlinx.coroutines.flow.emitAll
import kotlinx.coroutines.flow.Flow
import pod.core.mission.Mission
import pod.core.platform.MissionEvent
import pod.core.platform.Platform
import pod.core.platform.PlatformVehicle
import pod.core.platform.SafeState
import pod.core.vehicle.ConnectionState
import kotlin.time.Duration

/**
 * [fleet] with a journal of what the engine asked of it, in call order: every flight's end (and
 * whether the vehicle was lost then), every safe-state request, and each program's return.
 */
internal class JournalPlatform(private val fleet: FakeFleet, private val now: () -> Duration) : Platform by fleet {
    sealed interface Entry {
        data class FlightEnded(val vehicle: Int, val mission: String, val completed: Boolean, val lost: Boolean, val at: Duration) : Entry

        data class MadeSafe(val vehicle: Int, val at: Duration) : Entry

        data class ProgramReturned(val tag: String, val at: Duration) : Entry
    }

    val journal = mutableListOf<Entry>()

    override fun fly(vehicle: PlatformVehicle, mission: Mission): Flow<MissionEvent> = flow {
        var completed = false
        try {
            emitAll(fleet.fly(vehicle, mission))
            completed = true
        } finally {
            journal += Entry.FlightEnded(vehicle.id, mission.name, completed, fleet[vehicle.id].connection.value == ConnectionState.LOST, now())
        }
    }

    override suspend fun makeSafe(vehicle: PlatformVehicle, state: SafeState) {
        fleet.makeSafe(vehicle, state)
        journal += Entry.MadeSafe(vehicle.id, now())
    }

    fun programReturned(tag: String) {
        journal += Entry.ProgramReturned(tag, now())
    }
}
