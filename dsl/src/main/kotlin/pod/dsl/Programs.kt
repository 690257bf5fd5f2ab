package pod.dsl

import pod.core.engine.Engine
import pod.core.engine.EngineConfig
import pod.core.engine.PickRequest
import pod.core.engine.Program
import pod.core.engine.Region
import pod.core.engine.VehicleSet
import pod.core.platform.Platform
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.vehicle.VehicleType
import kotlin.time.Duration

/**
 * Runs [block] as a Dolphin program against this fleet and returns its result; vehicles it picked
 * are released when it ends, and vehicles its cancelled tasks flew are made safe.
 *
 * ```
 * platform.program {
 *     val v = pick { count(1); payload("camera") }
 *     execute(survey on v until { battery(v[0]) < 0.3 })
 *     execute(mission { returnHomeAndLand() } on v)
 *     release(v)
 * }
 * ```
 */
public suspend fun <T> Platform.program(config: EngineConfig = EngineConfig(), block: suspend Program.() -> T): T =
    Engine(this, config).run(block)

/** Waits for free vehicles that meet what [build] asks for and takes them (Dolphin `pick { … }`). */
public suspend fun Program.pick(build: PickBuilder.() -> Unit): VehicleSet = pick(PickBuilder().apply(build).request())

/** Sets how long a vehicle may go unheard during a task before the task fails (Dolphin `setConnectionTimeout`). */
public fun Program.setConnectionTimeout(timeout: Duration) {
    require(!timeout.isNegative()) { "setConnectionTimeout: timeout must be ≥ 0, was $timeout" }
    connectionTimeout = timeout
}

/** A point for regions: `location(41.18, -8.6)`. */
public fun location(latitude: Double, longitude: Double): Location = Location(latitude, longitude)

/** The area within [radius] of this point: `location(41.18, -8.6) radius 2.km`. */
public infix fun Location.radius(radius: Distance): Region = Region(this, radius)

/** What a pick asks for; every call narrows it. */
@PodDsl
public class PickBuilder internal constructor() {
    private var request = PickRequest()

    /** How many vehicles, ≥ 1 (default 1). */
    public fun count(count: Int) {
        require(count >= 1) { "pick: count must be ≥ 1, was $count" }
        request = request.copy(count = count)
    }

    /** Only these airframes. */
    public fun type(vararg types: VehicleType) {
        request = request.copy(types = request.types + types)
    }

    /** Only multirotors (any number of rotors). */
    public fun multirotor() {
        request = request.copy(types = request.types + VehicleType.entries.filter { it.isMultirotor })
    }

    /** Only vehicles with these ids. */
    public fun id(vararg ids: Int) {
        request = request.copy(ids = request.ids + ids.toSet())
    }

    /** Only vehicles that carry all of these payloads. */
    public fun payload(vararg payloads: String) {
        request = request.copy(payloads = request.payloads + payloads)
    }

    /** Only vehicles inside [region]. */
    public fun region(region: Region) {
        request = request.copy(region = region)
    }

    /** Only vehicles with at least [atLeast] (0..1) of their battery left. */
    public fun battery(atLeast: Double) {
        require(atLeast in 0.0..1.0) { "pick: battery must be in 0.0..1.0, was $atLeast" }
        request = request.copy(minBattery = atLeast)
    }

    /** Give up after [timeout] of vehicle time (default 60 s). */
    public fun timeout(timeout: Duration) {
        require(timeout.isPositive()) { "pick: timeout must be positive, was $timeout" }
        request = request.copy(timeout = timeout)
    }

    internal fun request(): PickRequest = request
}
