package pod.dsl

import kotlinx.coroutines.flow.flow
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import pod.core.mission.Mission
import pod.core.mission.MissionStep
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
import kotlin.time.Duration.Companion.seconds

/** A vehicle of [TinyFleet]. */
internal class TinyVehicle(override val id: Int) : PlatformVehicle {
    override val name = "tiny-$id"
    override val type = VehicleType.QUADROTOR
    override val payloads = kotlinx.coroutines.flow.MutableStateFlow(setOf("camera"))
    override val connection: StateFlow<ConnectionState> = MutableStateFlow(ConnectionState.CONNECTED)
    override val position: StateFlow<Position?> = MutableStateFlow(null)
    override val battery = MutableStateFlow<Battery?>(Battery(1.0, 16.8))
    override val home: StateFlow<Location?> = MutableStateFlow(null)
    override val landedState: StateFlow<LandedState> = MutableStateFlow(LandedState.ON_GROUND)
}

/**
 * The least fleet the DSL needs, in virtual time: 10 s and 10 % of battery per mission step.
 * Records finished missions and safe-state requests. (core's FakeFleet is test code of core.)
 */
internal class TinyFleet(count: Int) : Platform {
    val tiny = List(count) { TinyVehicle(it + 1) }
    override val vehicles: StateFlow<List<PlatformVehicle>> = MutableStateFlow(tiny)
    val completed = mutableListOf<Pair<Int, String>>()
    val madeSafe = mutableListOf<Int>()

    override fun fly(vehicle: PlatformVehicle, mission: Mission): Flow<MissionEvent> = flow {
        val battery = (vehicle as TinyVehicle).battery
        repeat(mission.steps.size) {
            delay(10.seconds)
            battery.value = Battery((battery.value?.remaining ?: 1.0) - 0.1, 16.8)
        }
        completed += vehicle.id to mission.name
    }

    override suspend fun makeSafe(vehicle: PlatformVehicle, state: SafeState) {
        madeSafe += vehicle.id
    }

    companion object {
        private val HOME = Location(41.18, -8.6)

        fun mission(name: String, steps: Int = 1) = Mission(name, HOME, List(steps) { MissionStep.Waypoint(HOME) })
    }
}
