package pod.core.platform

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.StateFlow
import pod.core.mission.Mission

/**
 * What the engine needs from a fleet: the vehicles it can use and a way to fly a mission on one.
 * What only some fleets can do (fly a mission queue, a survey workflow) is a capability the
 * engine discovers on the platform: [QueueCapable], [SurveyCapable].
 *
 * The MAVLink module implements it over a ground station (real or simulated vehicles); core's
 * tests implement it with a fake fleet in virtual time. The engine guarantees that it never asks
 * for two missions on one vehicle at once, and that a mission cancelled mid-flight is followed by
 * [makeSafe] before the cancelled task returns.
 */
public interface Platform {
    /** The vehicles currently known, in a stable order. Vehicles are added as they are discovered. */
    public val vehicles: StateFlow<List<PlatformVehicle>>

    /**
     * How many times faster than the wall clock the vehicles' world runs (a simulator's time scale);
     * program durations (`idle`, `during`, pick timeouts) are divided by it. 1 for real vehicles.
     */
    public val timeScale: Double get() = 1.0

    /**
     * The flight of [mission] on [vehicle], cold: collecting it flies the mission, emitting what
     * happens as it happens, and completes when the mission is complete as [Mission.completion]
     * defines (a mission ending in an unlimited loiter emits [MissionEvent.Loitering] and runs until
     * the collector is cancelled). Collecting throws a typed exception when the vehicle refuses,
     * fails or is lost ([pod.core.vehicle.VehicleLost]). Cancelling the collector ends the flight
     * promptly (with the CancellationException) without making the vehicle safe: the engine calls
     * [makeSafe] next.
     *
     * A flow rather than a callback so the engine hears each event in the flight's own coroutine, in
     * order, with nothing buffered between the vehicle's report and the engine's event.
     */
    public fun fly(vehicle: PlatformVehicle, mission: Mission): Flow<MissionEvent>

    /** Puts [vehicle] in [state] (hold where it is, or return home) and returns once it is confirmed. */
    public suspend fun makeSafe(vehicle: PlatformVehicle, state: SafeState)
}

/**
 * Marks a failure of a flight that the vehicle's own autopilot or its pilot ended by taking
 * control: a failsafe (a fence breach, a low battery), a mode switch on the transmitter, another
 * ground station. The engine leaves such a vehicle as they put it instead of making it safe its
 * own way ([Platform.makeSafe]), which would override them: a copter that breached its fence keeps
 * flying the autopilot's RTL rather than stopping outside the fence.
 */
public interface AutopilotTookControl

/** What a vehicle does when the task flying it is cancelled. */
public enum class SafeState {
    /** Stop and hold position (loiter for planes). */
    HOLD,

    /** Return to launch (multirotors land there). */
    RETURN_HOME,
}

/** Something that happened while a vehicle flew a mission. */
public sealed interface MissionEvent {
    /**
     * The mission is on board the vehicle.
     *
     * @property steps how many mission steps were uploaded.
     */
    public data class Uploaded(val steps: Int) : MissionEvent

    /**
     * The vehicle, on the ground, was got ready to fly it: [changes] in order, in words ("mode
     * STABILIZE → GUIDED", "armed"), so that no mode change comes as a surprise.
     *
     * @property changes what was changed, in order, in words; empty when the vehicle was ready as it was.
     */
    public data class Prepared(val changes: List<String>) : MissionEvent

    /** The vehicle started flying it. */
    public data object Started : MissionEvent

    /**
     * The vehicle began mission step [step].
     *
     * @property step the index of the step in [Mission.steps].
     */
    public data class StepStarted(val step: Int) : MissionEvent

    /**
     * The vehicle finished mission step [step].
     *
     * @property step the index of the step in [Mission.steps].
     */
    public data class StepDone(val step: Int) : MissionEvent

    /**
     * The vehicle is established on the unlimited loiter that ends the mission, step [step]: it
     * circles there until the task is cancelled (a mission ending so never completes).
     *
     * @property step the index of the loiter step in [Mission.steps].
     */
    public data class Loitering(val step: Int) : MissionEvent

    /** The mission is complete. */
    public data object Completed : MissionEvent
}
