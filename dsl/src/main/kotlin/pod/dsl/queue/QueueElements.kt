package pod.dsl.queue

import pod.core.engine.Task
import pod.core.engine.VehicleSet
import pod.core.mission.SurveyDirection
import pod.core.platform.PlatformVehicle
import pod.core.platform.SafeState
import pod.core.queue.MissionQueue
import pod.core.queue.QueueElement
import pod.core.queue.QueuePattern
import pod.core.queue.QueuePoint
import pod.core.queue.WhenEmpty
import pod.core.units.Distance
import pod.core.units.Location
import kotlin.time.Duration

// Elements for a MissionQueue, named as Paparazzi's mission interface names them. Points are
// metres from the vehicle's home (`at(north, east)`) or a Location's latitude and longitude;
// `altitude` is a height above home (null keeps the vehicle's), `duration` the longest the element
// lasts (null, zero or negative: no limit).

/** Go to [point]. */
public fun goto(point: QueuePoint, altitude: Distance? = null, duration: Duration? = null): QueueElement =
    QueueElement(QueuePattern.Goto(point), duration, altitude)

/** Go to the latitude and longitude of [location]. */
public fun goto(location: Location, altitude: Distance? = null, duration: Duration? = null): QueueElement =
    goto(QueuePoint.Global(location), altitude, duration)

/** Circle [center] at [radius]: positive clockwise, negative counter-clockwise; ends only by [duration] or `next()`. */
public fun circle(center: QueuePoint, radius: Distance, altitude: Distance? = null, duration: Duration? = null): QueueElement =
    QueueElement(QueuePattern.Circle(center, radius), duration, altitude)

/** Fly the segment from [from] to [to]. */
public fun segment(from: QueuePoint, to: QueuePoint, altitude: Distance? = null, duration: Duration? = null): QueueElement =
    QueueElement(QueuePattern.Segment(from, to), duration, altitude)

/** Fly through [points] in order. */
public fun path(vararg points: QueuePoint, altitude: Distance? = null, duration: Duration? = null): QueueElement =
    QueueElement(QueuePattern.Path(points.toList()), duration, altitude)

/** Fly through [points] in order. */
public fun path(points: List<QueuePoint>, altitude: Distance? = null, duration: Duration? = null): QueueElement =
    QueueElement(QueuePattern.Path(points), duration, altitude)

/** Survey the rectangle [length] × [width] from [start] toward [direction], tracks [spacing] apart. */
public fun survey(
    start: QueuePoint,
    length: Distance,
    width: Distance,
    spacing: Distance,
    direction: SurveyDirection = SurveyDirection.NORTH_EAST,
    altitude: Distance? = null,
    duration: Duration? = null,
): QueueElement = QueueElement(QueuePattern.Survey(start, length, width, spacing, direction), duration, altitude)

/** Hold where the vehicle is for [duration] (null: until `next()`). */
public fun hold(duration: Duration? = null, altitude: Distance? = null): QueueElement = QueueElement(QueuePattern.Hold, duration, altitude)

/** Land where the vehicle is. */
public fun land(): QueueElement = QueueElement(QueuePattern.Land)

/** Return to launch (multirotors land there). */
public fun returnHome(): QueueElement = QueueElement(QueuePattern.ReturnHome)

/**
 * A task that flies this queue on [vehicle] while the program feeds it; it completes when the
 * queue runs empty (the vehicle holding where it is), or goes on waiting with [WhenEmpty.WAIT].
 */
public fun MissionQueue.flownBy(vehicle: PlatformVehicle, whenEmpty: WhenEmpty = WhenEmpty.COMPLETE, onCancel: SafeState? = null): Task =
    Task.Bound(Task.FlyQueue(this, whenEmpty, onCancel), VehicleSet(listOf(vehicle)))

/** Fly this queue on [vehicle] until it runs empty (Dolphin's `task @ vehicle` for a queue). */
public infix fun MissionQueue.on(vehicle: PlatformVehicle): Task = flownBy(vehicle)
