package pod.core.engine

import pod.core.time.Timebase
import pod.core.platform.SafeState
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** How an [Engine] runs programs. */
public data class EngineConfig(
    /** What a vehicle does when its task is cancelled, unless the task says otherwise. */
    public val safeState: SafeState = SafeState.HOLD,
    /** How long a vehicle may stay unheard during a task before the task fails with VehicleLost (vehicle time). */
    public val connectionTimeout: Duration = Duration.ZERO,
    /** How long to wait for a vehicle to confirm its safe state (wall time). */
    public val safeTimeout: Duration = 10.seconds,
    /**
     * The clock events are stamped with and mission queues count on, with its dispatcher, one
     * value so they cannot disagree; tests pass the virtual one.
     */
    public val timebase: Timebase = Timebase.System,
)
