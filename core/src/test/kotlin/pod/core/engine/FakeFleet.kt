package pod.core.engine

import kotlinx.coroutines.flow.flow
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.update
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.platform.MissionEvent
import pod.core.platform.Platform
import pod.core.platform.PlatformVehicle
import pod.core.platform.SafeState
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Battery
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.LandedState
import pod.core.vehicle.Position
import pod.core.vehicle.VehicleType
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** A vehicle of [FakeFleet]: telemetry the test can set. */
internal class FakeVehicle(
    override val id: Int,
    override val type: VehicleType = VehicleType.QUADROTOR,
    payloads: Set<String> = setOf("camera"),
    at: Location = FakeFleet.HOME.offset((id * 10).m, 0.m),
) : PlatformVehicle {
    override val payloads = MutableStateFlow(payloads)
    override val name: String = "fake-$id"
    override val connection = MutableStateFlow(ConnectionState.CONNECTED)
    override val position = MutableStateFlow<Position?>(Position(at, 0.m, null, pod.core.units.Speed.ZERO, pod.core.units.Speed.ZERO, pod.core.units.Speed.ZERO))
    override val battery = MutableStateFlow<Battery?>(Battery(1.0, 16.8))
    override val home: StateFlow<Location?> = MutableStateFlow(at)
    override val landedState = MutableStateFlow(LandedState.ON_GROUND)

    fun setBattery(fraction: Double) {
        battery.value = Battery(fraction, 16.8)
    }
}

/**
 * A fleet in virtual time: flying a mission takes [stepTime] per step and drains [drainPerStep] of
 * battery per step. A mission named "fail…" fails after its first step. Records every flight and
 * every safe-state request, and whether a vehicle was ever asked to fly twice at once.
 */
internal class FakeFleet(
    count: Int,
    private val stepTime: Duration = 10.seconds,
    private val drainPerStep: Double = 0.0,
    override val timeScale: Double = 1.0,
) : Platform {
    val fakes: List<FakeVehicle> = (1..count).map { FakeVehicle(it) }
    override val vehicles = MutableStateFlow<List<PlatformVehicle>>(fakes)

    private val flying = MutableStateFlow<Map<Int, Int>>(emptyMap())
    val overlaps = MutableStateFlow(0)
    val flights = MutableStateFlow<List<Pair<Int, String>>>(emptyList())
    val completed = MutableStateFlow<List<Pair<Int, String>>>(emptyList())
    val madeSafe = MutableStateFlow<List<Pair<Int, SafeState>>>(emptyList())

    /** Vehicles in the air right now. */
    val airborne: Set<Int> get() = flying.value.filterValues { it > 0 }.keys

    operator fun get(id: Int): FakeVehicle = fakes.first { it.id == id }

    override fun fly(vehicle: PlatformVehicle, mission: Mission): Flow<MissionEvent> = flow {
        val fake = vehicle as FakeVehicle
        flights.update { it + (vehicle.id to mission.name) }
        flying.update { it + (vehicle.id to (it[vehicle.id] ?: 0) + 1) }
        if ((flying.value[vehicle.id] ?: 0) > 1) overlaps.update { it + 1 }
        try {
            fake.landedState.value = LandedState.IN_AIR
            emit(MissionEvent.Uploaded(mission.steps.size))
            emit(MissionEvent.Started)
            mission.steps.forEachIndexed { index, _ ->
                emit(MissionEvent.StepStarted(index))
                delay(stepTime)
                fake.setBattery(((fake.battery.value?.remaining ?: 1.0) - drainPerStep).coerceAtLeast(0.0))
                emit(MissionEvent.StepDone(index))
                if (mission.name.startsWith("failsafe")) throw TookControl("${mission.name}: the autopilot of ${vehicle.name} took control")
                if (mission.name.startsWith("fail")) error("${mission.name} failed on ${vehicle.name}")
            }
            if (mission.completion == pod.core.mission.MissionCompletion.LANDED) fake.landedState.value = LandedState.ON_GROUND
            emit(MissionEvent.Completed)
            completed.update { it + (vehicle.id to mission.name) }
        } finally {
            flying.update { it + (vehicle.id to (it[vehicle.id] ?: 1) - 1) }
        }
    }

    override suspend fun makeSafe(vehicle: PlatformVehicle, state: SafeState) {
        delay(1.seconds)
        madeSafe.update { it + (vehicle.id to state) }
    }

    companion object {
        val HOME = Location(41.18, -8.6)

        /** A mission of [steps] waypoints named [name]. */
        fun mission(name: String, steps: Int = 3, land: Boolean = false): Mission = Mission(
            name,
            HOME,
            List(steps) { MissionStep.Waypoint(HOME.offset((it * 20).m, 0.m, 20.m)) } + if (land) listOf(MissionStep.ReturnHome) else emptyList(),
        )
    }
}

/** A flight the vehicle's autopilot ended by taking control (a fence breach, a failsafe). */
class TookControl(message: String) : Exception(message), pod.core.platform.AutopilotTookControl
