package pod.bench.engine

import kotlinx.coroutines.flow.flow
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.yield
import pod.core.mission.Mission
import pod.core.platform.MissionEvent
import pod.core.platform.Platform
import pod.core.platform.PlatformVehicle
import pod.core.platform.SafeState
import pod.core.units.Location
import pod.core.vehicle.Battery
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.LandedState
import pod.core.vehicle.Position
import pod.core.vehicle.VehicleType

/** A vehicle that never changes: the engine reads its flows, nothing writes them. */
class InstantVehicle(override val id: Int) : PlatformVehicle {
    override val name: String = "v$id"
    override val type: VehicleType = VehicleType.QUADROTOR
    override val payloads: kotlinx.coroutines.flow.StateFlow<Set<String>> = kotlinx.coroutines.flow.MutableStateFlow(emptySet())
    override val connection: StateFlow<ConnectionState> = MutableStateFlow(ConnectionState.CONNECTED)
    override val position: StateFlow<Position?> = MutableStateFlow(null)
    override val battery: StateFlow<Battery?> = MutableStateFlow(Battery(1.0, 16.8))
    override val home: StateFlow<Location?> = MutableStateFlow(null)
    override val landedState: StateFlow<LandedState> = MutableStateFlow(LandedState.ON_GROUND)
}

/**
 * A fleet of [count] vehicles whose missions finish at once (after one [yield] when [yielding]),
 * reporting Uploaded, Started and Completed, so that what is measured is the engine alone.
 */
class InstantPlatform(count: Int, private val yielding: Boolean) : Platform {
    val fleet: List<InstantVehicle> = List(count) { InstantVehicle(it + 1) }
    override val vehicles: StateFlow<List<PlatformVehicle>> = MutableStateFlow(fleet)

    override fun fly(vehicle: PlatformVehicle, mission: Mission): Flow<MissionEvent> = flow {
        emit(MissionEvent.Uploaded(mission.steps.size))
        emit(MissionEvent.Started)
        if (yielding) yield()
        emit(MissionEvent.Completed)
    }

    override suspend fun makeSafe(vehicle: PlatformVehicle, state: SafeState) = Unit
}
