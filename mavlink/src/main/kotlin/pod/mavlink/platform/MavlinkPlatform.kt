package pod.mavlink.platform

import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.emitAll
import kotlinx.coroutines.flow.flow
import kotlinx.coroutines.flow.flatMapLatest
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.launch
import pod.core.mission.Mission
import pod.core.platform.MissionEvent
import pod.core.platform.Platform
import pod.core.platform.PlatformVehicle
import pod.core.platform.QueueCapable
import pod.core.platform.SurveyCapable
import pod.core.platform.SafeState
import pod.mavlink.GroundStation
import pod.mavlink.MavlinkVehicle
import pod.mavlink.executor.ExecutorTiming
import pod.mavlink.executor.MissionExecutor

/**
 * The engine's [Platform] over a [GroundStation]: every vehicle the station hears that is usable,
 * in system-id order; [fly] runs a [MissionExecutor]; [makeSafe] holds (BRAKE on an ArduCopter; a
 * plane circles) or returns to launch, confirmed by the vehicle's mode.
 *
 * A vehicle is offered to the engine (and so to `pick`) only once its home and its position are
 * known: a real autopilot has no home until its estimator sets an origin, tens of seconds after
 * boot, and a program must be able to read `v.home.value` of a vehicle it picked. Until then the
 * vehicle is listed in [initialising] with what it still lacks. The list follows the station for
 * as long as the station runs.
 */
public class MavlinkPlatform(
    /** The station the vehicles are heard on. */
    public val station: GroundStation,
    /** How much faster than the wall clock the vehicles' world runs (1 for real vehicles). */
    override val timeScale: Double = 1.0,
    /** Time limits of every mission run. */
    public val timing: ExecutorTiming = ExecutorTiming(),
    /**
     * What each vehicle carries, when the app knows better than the vehicle says (a gripper on
     * vehicle 3), asked once per vehicle; null (the default): what each vehicle reports
     * ([MavlinkVehicle.payloads]), as it reports it.
     */
    private val payloads: ((MavlinkVehicle) -> Set<String>)? = null,
    /** How queue tasks fly ([pod.mavlink.queue.QueueFlight]). */
    public val queueFlight: pod.mavlink.queue.QueueFlightConfig = pod.mavlink.queue.QueueFlightConfig(),
) : Platform, QueueCapable, SurveyCapable {
    private val adapters = HashMap<Int, MavlinkPlatformVehicle>()
    private val _vehicles = MutableStateFlow(adapt(usable(station.vehicles.value.values.map { it to lacking(it) })))
    private val _initialising = MutableStateFlow(unusable(station.vehicles.value.values.map { it to lacking(it) }))

    init {
        require(timeScale > 0 && timeScale.isFinite()) { "timeScale must be a positive number, was $timeScale" }
        station.scope.launch(CoroutineName("platform-vehicles")) {
            @OptIn(ExperimentalCoroutinesApi::class)
            station.vehicles.flatMapLatest { heard ->
                if (heard.isEmpty()) {
                    flowOf(emptyList())
                } else {
                    combine(heard.values.map { v -> combine(v.telemetry.home, v.telemetry.position) { _, _ -> v to lacking(v) } }) { it.toList() }
                }
            }.collect { states ->
                _vehicles.value = adapt(usable(states))
                _initialising.value = unusable(states)
            }
        }
    }

    override val vehicles: StateFlow<List<PlatformVehicle>> = _vehicles.asStateFlow()

    /**
     * Vehicles heard but not yet offered to the engine, by system id, each with what it still
     * lacks ("home", "position", "home and position"): what a UI shows while a fleet boots.
     */
    public val initialising: StateFlow<Map<Int, String>> = _initialising.asStateFlow()

    override fun fly(vehicle: PlatformVehicle, mission: Mission): Flow<MissionEvent> =
        flow { emitAll(MissionExecutor(mavlink(vehicle), mission, timing).run()) }

    /** Flies [queue] on [vehicle] in its guided mode ([pod.mavlink.queue.QueueFlight]). */
    override suspend fun flyQueue(vehicle: PlatformVehicle, queue: pod.core.queue.MissionQueue, whenEmpty: pod.core.queue.WhenEmpty) {
        pod.mavlink.queue.QueueFlight(mavlink(vehicle), queue, queueFlight).fly(whenEmpty)
    }

    /** Flies the survey workflow [job] on [vehicle] ([pod.mavlink.workflow.SurveyWorkflow], or [pod.mavlink.workflow.SurveyOperation] when it serves a mission control). */
    override suspend fun flySurvey(vehicle: PlatformVehicle, job: pod.core.workflow.SurveyJob<*, *>) {
        pod.mavlink.workflow.flySurveyJob(mavlink(vehicle), job, timeScale, queueFlight)
    }

    /**
     * Holds ([SafeState.HOLD]: [VehicleActions.hold][pod.mavlink.action.VehicleActions.hold], a
     * mode that keeps altitude with nobody on the sticks) or returns to launch
     * ([SafeState.RETURN_HOME]) and returns once the vehicle's mode confirms it. A disarmed vehicle
     * is left in its mode, whatever its landed state says (UNDEFINED until EXTENDED_SYS_STATE is
     * streamed): no mode holds a vehicle whose motors are off, and the hold mode would stop the next
     * flight (ArduCopter will not arm in BRAKE: "Arm: Mode not armable").
     */
    override suspend fun makeSafe(vehicle: PlatformVehicle, state: SafeState) {
        val v = mavlink(vehicle)
        if (!v.telemetry.armed.value) return
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

    /** What [v] lacks to be usable, or null when its home and position are known. */
    private fun lacking(v: MavlinkVehicle): String? {
        val missing = listOfNotNull("home".takeIf { v.telemetry.home.value == null }, "position".takeIf { v.telemetry.position.value == null })
        return missing.takeIf { it.isNotEmpty() }?.joinToString(" and ")
    }

    private fun usable(states: List<Pair<MavlinkVehicle, String?>>): Map<Int, MavlinkVehicle> =
        states.filter { it.second == null }.associate { it.first.systemId to it.first }

    private fun unusable(states: List<Pair<MavlinkVehicle, String?>>): Map<Int, String> =
        states.mapNotNull { (v, lacking) -> lacking?.let { v.systemId to it } }.toMap()

    private fun adapt(heard: Map<Int, MavlinkVehicle>): List<PlatformVehicle> = synchronized(adapters) {
        heard.toSortedMap().map { (id, v) ->
            adapters[id]?.takeIf { it.vehicle === v } ?: MavlinkPlatformVehicle(v, payloads?.let { MutableStateFlow(it(v)).asStateFlow() } ?: v.payloads).also { adapters[id] = it }
        }
    }

}
