package pod.dsl

import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Speed
import pod.core.units.deg
import pod.core.units.km
import pod.core.units.m
import pod.core.units.mps
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours

/** The ranges the `mission { }` builder accepts (docs/dsl-missions.md lists them too). */
internal object MissionLimits {
    val height: ClosedRange<Distance> = 0.m..10.km
    val homeAltitude: ClosedRange<Distance> = (-1).km..10.km
    val takeOffHeight: ClosedRange<Distance> = 1.m..10.km
    val radius: ClosedRange<Distance> = 1.m..10.km
    val offset: ClosedRange<Distance> = (-50).km..50.km
    val spacing: ClosedRange<Distance> = 1.m..10.km
    val latitude: ClosedRange<Double> = -90.0..90.0
    val longitude: ClosedRange<Double> = -180.0..180.0
    val pitch: ClosedRange<Angle> = 0.deg..90.deg
    val yaw: ClosedRange<Angle> = 0.deg..360.deg
    val delay: ClosedRange<Duration> = Duration.ZERO..24.hours
    val turns: IntRange = 1..1000
    val photoCount: IntRange = 1..10_000
    val areaSide: Distance = 50.km
    val speed: Speed = 100.mps
    val captureInterval: Duration = 1.hours
    val loiterTime: Duration = 24.hours

    /** Keeps a survey within what a MAVLink mission (a few thousand items at most) can carry. */
    const val SURVEY_TRACKS: Int = 1000
}

/** Fails with "command: argument must be in a..b, was v" unless [value] is in [range] (NaN never is). */
internal fun <T : Comparable<T>> requireIn(command: String, argument: String, value: T, range: ClosedRange<T>) {
    require(value in range) { "$command: $argument must be in ${range.start}..${range.endInclusive}, was $value" }
}

/** Fails with "command: argument must be in 1..1000, was v" unless [value] is in [range]. */
internal fun requireIn(command: String, argument: String, value: Int, range: IntRange) {
    require(value in range) { "$command: $argument must be in $range, was $value" }
}

/** Fails unless [value] is greater than [zero] and at most [max] (NaN never is). */
internal fun <T : Comparable<T>> requirePositive(command: String, argument: String, value: T, zero: T, max: T) {
    require(value > zero && value <= max) { "$command: $argument must be greater than $zero and at most $max, was $value" }
}
