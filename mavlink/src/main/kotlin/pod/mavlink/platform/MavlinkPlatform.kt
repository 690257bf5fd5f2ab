package pod.mavlink.platform

import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.launch
import pod.core.mission.Mission
import pod.core.platform.MissionEvent
import pod.core.platform.Platform
import pod.core.platform.PlatformVehicle
import pod.core.platform.SafeState
import pod.core.vehicle.LandedState
import pod.mavlink.GroundStation
import pod.mavlink.MavlinkVehicle
import pod.mavlink.executor.ExecutorTiming
import pod.mavlink.executor.MissionExecutor

/**
 * The engine's [Platform] over a [GroundStation]: every vehicle the station hears, in system-id
 * order; [fly] runs a [MissionExecutor]; [makeSafe] holds (BRAKE on an ArduCopter; a plane circles) or returns to
 * launch, confirmed by the vehicle's mode.
 *
 * The vehicle list follows the station for as long as the station runs.
 */
public class MavlinkPlatform(
    /** The station the vehicles are heard on. */
    public val station: GroundStation,
    /** How much faster than the wall clock the vehicles' world runs (1 for real vehicles). */
    override val timeScale: Double = 1.0,
    /** Time limits of every mission run. */
    public val timing: ExecutorTiming = ExecutorTiming(),
    /** What each vehicle carries, asked once per vehicle when it is first heard. */
    private val payloads: (MavlinkVehicle) -> Set<String> = { DEFAULT_PAYLOADS },
) : Platform {
    private val adapters = HashMap<Int, MavlinkPlatformVehicle>()
    private val _vehicles = MutableStateFlow(adapt(station.vehicles.value))

    init {
        require(timeScale > 0 && timeScale.isFinite()) { "timeScale must be a positive number, was $timeScale" }
        station.scope.launch(CoroutineName("platform-vehicles")) {
            station.vehicles.collect { _vehicles.value = adapt(it) }
        }
    }

    override val vehicles: StateFlow<List<PlatformVehicle>> = _vehicles.asStateFlow()

    override suspend fun fly(vehicle: PlatformVehicle, mission: Mission, report: suspend (MissionEvent) -> Unit) {
        MissionExecutor(mavlink(vehicle), mission, timing).run(report)
    }

    /**
     * Holds ([SafeState.HOLD]: [VehicleActions.hold][pod.mavlink.action.VehicleActions.hold], a
     * mode that keeps altitude with nobody on the sticks) or returns to launch
     * ([SafeState.RETURN_HOME]) and returns once the vehicle's mode confirms it. A vehicle on the
     * ground and disarmed is safe as it is.
     */
    override suspend fun makeSafe(vehicle: PlatformVehicle, state: SafeState) {
        val v = mavlink(vehicle)
        if (!v.telemetry.armed.value && v.telemetry.landedState.value == LandedState.ON_GROUND) return
        when (state) {
            SafeState.HOLD -> v.action.hold()
            SafeState.RETURN_HOME -> v.action.returnToLaunch()
        }
    }

    /** The MAVLink vehicle behind [vehicle]; throws IllegalArgumentException for a vehicle of another platform. */
    public fun mavlink(vehicle: PlatformVehicle): MavlinkVehicle =
        (vehicle as? MavlinkPlatformVehicle)?.vehicle?.takeIf { station.vehicles.value[it.systemId] === it }
            ?: station.vehicles.value[vehicle.id]
            ?: throw IllegalArgumentException("$vehicle is not a vehicle of this platform")

    private fun adapt(heard: Map<Int, MavlinkVehicle>): List<PlatformVehicle> = synchronized(adapters) {
        heard.toSortedMap().map { (id, v) ->
            adapters[id]?.takeIf { it.vehicle === v } ?: MavlinkPlatformVehicle(v, payloads(v)).also { adapters[id] = it }
        }
    }

    public companion object {
        /** What a vehicle carries unless the payload function says otherwise. */
        public val DEFAULT_PAYLOADS: Set<String> = setOf("camera")
    }
}
