package pod.core.engine

import pod.core.platform.PlatformVehicle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.VehicleType
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * What a `pick` asks for: [count] free, connected vehicles that meet every given requirement,
 * within [timeout] (vehicle time). pod-dsl's `pick { count(2); type(…); region(…) }` builds one.
 */
public data class PickRequest(
    /** How many vehicles. */
    public val count: Int = 1,
    /** Acceptable airframes, or empty for any. */
    public val types: Set<VehicleType> = emptySet(),
    /** Acceptable vehicle ids, or empty for any. */
    public val ids: Set<Int> = emptySet(),
    /** Payloads every picked vehicle must carry. */
    public val payloads: Set<String> = emptySet(),
    /** The area the vehicles must be in, or null for anywhere. */
    public val region: Region? = null,
    /** Smallest remaining battery charge, 0..1, or null for any; a vehicle that reports no charge does not meet it. */
    public val minBattery: Double? = null,
    /** How long to wait for enough vehicles. */
    public val timeout: Duration = DEFAULT_TIMEOUT,
) {
    init {
        require(count >= 1) { "pick: count must be ≥ 1, was $count" }
        require(minBattery == null || minBattery in 0.0..1.0) { "pick: battery must be in 0.0..1.0, was $minBattery" }
        require(timeout.isPositive()) { "pick: timeout must be positive, was $timeout" }
    }

    /** True when [vehicle] meets every requirement except being free; reads through [scope] so waits are woken by changes. */
    public fun accepts(vehicle: PlatformVehicle, scope: ConditionScope): Boolean {
        if (types.isNotEmpty() && vehicle.type !in types) return false
        if (ids.isNotEmpty() && vehicle.id !in ids) return false
        if (payloads.isNotEmpty() && !scope.read(vehicle.payloads).containsAll(payloads)) return false
        if (scope.read(vehicle.connection) != ConnectionState.CONNECTED) return false
        // A vehicle whose charge is unknown (NaN) does not meet a battery requirement until it reports one.
        if (minBattery != null && !(scope.battery(vehicle) >= minBattery)) return false
        if (region != null) {
            val at = scope.position(vehicle)?.location ?: return false
            if (region.center.distanceTo(at) > region.radius) return false
        }
        return true
    }

    /** The request in words, for errors: "2 vehicles of type QUADROTOR with payload camera". */
    public fun describe(): String = buildString {
        append(if (count == 1) "1 vehicle" else "$count vehicles")
        if (types.isNotEmpty()) append(" of type ").append(types.joinToString(" or "))
        if (ids.isNotEmpty()) append(" with id ").append(ids.joinToString(" or "))
        if (payloads.isNotEmpty()) append(" with payload ").append(payloads.joinToString(" and "))
        if (region != null) append(" within ").append(region.radius).append(" of ").append(region.center)
        if (minBattery != null) append(" with battery ≥ ").append((minBattery * 100).toInt()).append('%')
    }

    /** The defaults a pick falls back on. */
    public companion object {
        /** How long a pick waits unless told otherwise. */
        public val DEFAULT_TIMEOUT: Duration = 60.seconds
    }
}

/** A circular area: within [radius] of [center] (altitude ignored). */
public data class Region(
    /** Middle of the area. */
    public val center: Location,
    /** How far from it. */
    public val radius: Distance,
) {
    init {
        require(radius.meters > 0) { "region: radius must be positive, was $radius" }
    }
}
