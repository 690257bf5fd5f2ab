package pod.samples

import pod.core.engine.PickTimeout
import pod.core.engine.Program
import pod.core.engine.Task
import pod.core.engine.VehicleSet
import pod.core.mission.Mission
import pod.core.platform.PlatformVehicle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.airborne
import pod.dsl.action
import pod.dsl.and
import pod.dsl.concurrently
import pod.dsl.during
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.dsl.then
import pod.dsl.until
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/*
 * The Dolphin report's listings, written with Pod's DSL. Each is a program: a suspend function on
 * Program, so it runs on any platform — simulated vehicles (see Main.kt and `./pod demo`), real
 * ones over MAVLink, or core's fake fleet.
 */

/** Where a vehicle took off, falling back to where it is. */
internal fun homeOf(v: PlatformVehicle): Location {
    val at = v.home.value ?: v.position.value?.location ?: error("${v.name} has reported neither home nor position")
    return Location(at.latitude, at.longitude) // mission heights are above home
}

/** True while [v] is off the ground (see [pod.core.vehicle.isAirborne]). */
internal fun isOut(v: PlatformVehicle): Boolean = v.airborne

/**
 * A lawn-mower survey of a [length] × [width] rectangle whose south-west corner is [north]/[east] of
 * [v]'s home; it ends back home on the ground, or over the last track when not [land]ing (flown
 * again from the air, its take-off is already done).
 */
internal fun surveyOf(v: PlatformVehicle, north: Distance, east: Distance, length: Distance = 120.m, width: Distance = 80.m, height: Distance = 30.m, land: Boolean = true): Mission {
    val home = homeOf(v)
    return mission("survey ${v.name}") {
        home(home)
        takeOff(height)
        moveFromHome(north, east, height)
        surveyArea(length, width, spacing = 20.m)
        if (land) returnHomeAndLand()
    }
}

/** Back to launch and land. */
internal fun landAtHome(v: PlatformVehicle): Mission {
    val home = homeOf(v)
    return mission("land ${v.name}") {
        home(home)
        goPos(home.latitude, home.longitude, 30.m)
        returnHomeAndLand()
    }
}

/**
 * Listing 1, with drones: pick three vehicles with cameras and survey three neighbouring areas
 * at once; release them when all three are back.
 */
suspend fun Program.listing1(): VehicleSet {
    val vehicles = pick { count(3); payload("camera") }
    message("listing 1: ${vehicles.joinToString { it.name }} survey three areas at once")
    execute(concurrently(vehicles.mapIndexed { i, v -> surveyOf(v, north = 40.m, east = (i * 100).m) on v }))
    release(vehicles)
    return vehicles
}

/**
 * Listing 2: one vehicle surveys until its battery falls below [lowBattery], then returns home and
 * lands (at once if the survey ends first).
 */
suspend fun Program.listing2(lowBattery: Double = 0.3): PlatformVehicle {
    val picked = pick { count(1) }
    val v = picked[0]
    message("listing 2: ${v.name} surveys until its battery is below ${(lowBattery * 100).toInt()} %")
    val survey = surveyOf(v, north = 40.m, east = 0.m, length = 400.m, width = 300.m)
    execute((survey on v) until { battery(v) < lowBattery })
    if (isOut(v)) {
        message("listing 2: ${v.name} battery low (${(battery(v) * 100).toInt()} %), returning home")
        execute(landAtHome(v) on v)
    }
    release(picked)
    return v
}

/**
 * Listing 2 as the Dolphin report writes it: take off, move out, loiter there indefinitely
 * (`moveAndLoiterPos`) until the battery falls below [lowBattery], then return home and land.
 * The loiter never ends by itself: `until` ends it. [out] is how far north the vehicle loiters,
 * [height] its cruise height and [radius] the circle's (a plane needs a wide one).
 */
suspend fun Program.loiterUntilLowBattery(lowBattery: Double = 0.3, out: Distance = 150.m, height: Distance = 30.m, radius: Distance = 15.m): PlatformVehicle {
    val picked = pick { count(1) }
    val v = picked[0]
    val home = homeOf(v)
    message("listing 2: ${v.name} loiters ${out.meters.toInt()} m out until its battery is below ${(lowBattery * 100).toInt()} %")
    val watch = mission("loiter ${v.name}") {
        home(home)
        takeOff(height)
        move(north = out)
        moveAndLoiterPos(radius = radius)
    }
    execute((watch on v) until { battery(v) < lowBattery })
    message("listing 2: ${v.name} battery at ${(battery(v) * 100).toInt()} %, returning home")
    execute(mission("home ${v.name}") { home(home); returnHomeAndLand() } on v)
    release(picked)
    return v
}

/** Listing 3: two vehicles survey two areas concurrently, each returning home when done. */
suspend fun Program.listing3(): VehicleSet {
    val vehicles = pick { count(2) }
    val (a, b) = vehicles.members
    message("listing 3: ${a.name} and ${b.name} survey side by side")
    execute((surveyOf(a, north = 40.m, east = 0.m) on a) and (surveyOf(b, north = 40.m, east = 120.m) on b))
    release(vehicles)
    return vehicles
}

/**
 * Listing 4: keep [airborne] vehicles on survey for [duration]. Each slot picks a charged vehicle
 * (battery ≥ [charged]) and keeps it surveying, round after round without landing, until its
 * battery is below [lowBattery]; then, if a
 * charged replacement is free, the replacement takes over the survey while the tired vehicle flies
 * home alongside (Dolphin's `|`), otherwise the vehicle comes home first and the slot waits for
 * one to charge. When [duration] has passed, every vehicle still out holds and is brought home.
 */
suspend fun Program.listing4(
    duration: Duration = 45.minutes,
    airborne: Int = 2,
    charged: Double = 0.9,
    lowBattery: Double = 0.3,
): Unit {
    message("listing 4: keeping $airborne vehicles on survey for $duration")
    // The vehicles this listing took: only those are its to bring home (another program, such as
    // the demo's queue tour, may be flying others).
    val taken: MutableSet<Int> = java.util.concurrent.ConcurrentHashMap.newKeySet()
    val slots = (1..airborne).map { slot -> action("slot $slot") { keepOnSurvey(slot, charged, lowBattery, taken) } }
    execute(concurrently(slots) during duration)
    val out = vehicles.filter { it.id in taken && isOut(it) }
    if (out.isNotEmpty()) {
        message("listing 4: time is up; bringing ${out.joinToString { it.name }} home")
        execute(concurrently(out.map { landAtHome(it) on it }))
    }
}

private suspend fun Program.keepOnSurvey(slot: Int, charged: Double, lowBattery: Double, taken: MutableSet<Int>) {
    var v = pick { count(1); battery(atLeast = charged); timeout(2.hours) }[0].also { taken += it.id }
    var homeward: Task? = null
    while (true) {
        message("slot $slot: ${v.name} takes the survey (battery ${percent(battery(v))})")
        val current = v
        val survey = action("survey loop ${current.name}") {
            while (battery(current) >= lowBattery) {
                execute((surveyOf(current, north = 40.m, east = (slot - 1) * 150.m, length = 300.m, width = 120.m, land = false) on current) until { battery(current) < lowBattery })
            }
        }
        execute(homeward?.let { survey and it } ?: survey)
        homeward = action("home ${current.name}") {
            if (isOut(current)) execute(landAtHome(current) on current)
            release(current)
        }
        val next = try {
            pick { count(1); battery(atLeast = charged); timeout(5.seconds) }[0].also { taken += it.id }
        } catch (e: PickTimeout) {
            null
        }
        message("slot $slot: ${current.name} battery low (${percent(battery(current))}), " + if (next != null) "${next.name} takes over" else "no charged vehicle: returning first")
        if (next == null) {
            execute(homeward)
            homeward = null
            v = pick { count(1); battery(atLeast = charged); timeout(2.hours) }[0].also { taken += it.id }
        } else {
            v = next
        }
    }
}

private fun percent(fraction: Double) = "${(fraction * 100).toInt()} %"

private operator fun Int.times(d: Distance): Distance = d * toDouble()
