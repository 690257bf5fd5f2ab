package pod.core.engine

import kotlinx.coroutines.flow.StateFlow
import pod.core.platform.PlatformVehicle
import pod.core.vehicle.Position

/**
 * A condition over live state, such as `battery(v) < 0.3`. The engine evaluates it, notes every
 * [StateFlow] it read through its [ConditionScope], and evaluates it again only when one of those
 * changes — no polling. A condition that reads no flow is evaluated again whenever the program's
 * own state changes (a task starts or ends, a vehicle is picked or released, a message is sent).
 */
public fun interface Condition {
    /** True when the condition holds now. */
    public fun ConditionScope.holds(): Boolean
}

/** What a [Condition] may read; every read is tracked so the engine knows when to look again. */
public interface ConditionScope {
    /** The current value of [flow], noted as something this condition depends on. */
    public fun <T> read(flow: StateFlow<T>): T

    /**
     * Remaining battery charge of [vehicle], 0..1, or NaN while it reports none (no battery status
     * yet, or a pack it cannot estimate). Unknown never counts as full, nor as empty: every comparison
     * with NaN is false, so `battery(v) < 0.3` does not fire and `battery(v) > 0.5` does not hold
     * until the vehicle says. Ask [batteryKnown] to tell the two apart.
     */
    public fun battery(vehicle: PlatformVehicle): Double = read(vehicle.battery)?.remaining ?: Double.NaN

    /** True once [vehicle] reports its remaining charge (see [battery]). */
    public fun batteryKnown(vehicle: PlatformVehicle): Boolean = read(vehicle.battery)?.remaining != null

    /** Where [vehicle] is, or null before its first position report. */
    public fun position(vehicle: PlatformVehicle): Position? = read(vehicle.position)

    /**
     * True while [vehicle] circles the unlimited loiter that ends the mission it is flying
     * ([pod.core.platform.MissionEvent.Loitering]), from the moment it is established on the
     * circle until that task ends: `waitFor { loitering(v) }`. False where no engine tracks it.
     */
    public fun loitering(vehicle: PlatformVehicle): Boolean = false
}

/** A condition that holds when both hold. */
public infix fun Condition.and(other: Condition): Condition = Condition { with(this@and) { holds() } && with(other) { holds() } }

/** A condition that holds when either holds. */
public infix fun Condition.or(other: Condition): Condition = Condition { with(this@or) { holds() } || with(other) { holds() } }

/** A condition that holds when this one does not. */
public operator fun Condition.not(): Condition = Condition { !with(this@not) { holds() } }
