package pod.cli.queue

import kotlinx.serialization.SerialName
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonClassDiscriminator
import pod.cli.json.Finite
import pod.core.mission.SurveyDirection
import pod.core.queue.QueueElement
import pod.core.queue.QueueEntry
import pod.core.queue.QueuePattern
import pod.core.queue.QueuePoint
import pod.core.queue.QueueStatus
import pod.core.units.Location
import pod.core.units.m
import kotlin.math.floor
import kotlin.math.roundToLong
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds

// The queue's values as JSON, for the control protocol and for `pod queue … --json`. Core stays
// free of serialization: these mirror QueuePoint, QueuePattern, QueueElement, QueueEntry and
// QueueStatus field by field, in the units the CLI prints (metres, seconds). A sealed type's kind
// is its `type` field, also inside `--json` events (whose own kind is `event`).

/** A point of a queued pattern: metres from home (`local`) or a latitude and longitude (`global`). */
@OptIn(ExperimentalSerializationApi::class)
@Serializable @JsonClassDiscriminator("type")
public sealed interface PointJson {
    /** [north] and [east] metres from the vehicle's home. */
    @Serializable @SerialName("local")
    public data class Local(val north: Double, val east: Double) : PointJson

    /** A latitude and longitude in degrees. */
    @Serializable @SerialName("global")
    public data class Global(val lat: Double, val lon: Double) : PointJson
}

/** A navigation pattern; see [QueuePattern] for what each flies. */
@OptIn(ExperimentalSerializationApi::class)
@Serializable @JsonClassDiscriminator("type")
public sealed interface PatternJson {
    /** Go to [point]. */
    @Serializable @SerialName("goto")
    public data class Goto(val point: PointJson) : PatternJson

    /** Circle [center] at [radius] metres, positive clockwise. */
    @Serializable @SerialName("circle")
    public data class Circle(val center: PointJson, val radius: Double) : PatternJson

    /** Fly from [from] to [to]. */
    @Serializable @SerialName("segment")
    public data class Segment(val from: PointJson, val to: PointJson) : PatternJson

    /** Fly through [points] in order. */
    @Serializable @SerialName("path")
    public data class Path(val points: List<PointJson>) : PatternJson

    /** A lawn-mower survey of [length] × [width] metres from [start], tracks [spacing] apart, toward [direction] (NORTH_EAST…). */
    @Serializable @SerialName("survey")
    public data class Survey(val start: PointJson, val length: Double, val width: Double, val spacing: Double, val direction: String) : PatternJson

    /** Hold where the vehicle is. */
    @Serializable @SerialName("hold")
    public data object Hold : PatternJson

    /** Land where the vehicle is. */
    @Serializable @SerialName("land")
    public data object Land : PatternJson

    /** Return to launch. */
    @Serializable @SerialName("return_home")
    public data object ReturnHome : PatternJson
}

/** A queue element: [pattern], its limit in seconds ([durationS], null: none) and its height above home ([altM], null: keep the vehicle's). */
@Serializable
public data class ElementJson(
    val pattern: PatternJson,
    @SerialName("duration_s") val durationS: Double? = null,
    @SerialName("alt_m") val altM: Double? = null,
)

/** An element in the queue, with the [id] the queue gave it. */
@Serializable
public data class EntryJson(val id: Long, val element: ElementJson)

/** What the queue holds: the [current] entry, what is left of its duration ([remainingS], null: unlimited) and the [pending] ones in order. */
@Serializable
public data class StatusJson(
    val current: EntryJson?,
    @SerialName("remaining_s") val remainingS: Finite?,
    val pending: List<EntryJson>,
)

/** [QueuePoint] as JSON. */
internal fun QueuePoint.toJson(): PointJson = when (this) {
    is QueuePoint.Local -> PointJson.Local(north.meters, east.meters)
    is QueuePoint.Global -> PointJson.Global(location.latitude, location.longitude)
}

/** [QueuePattern] as JSON. */
internal fun QueuePattern.toJson(): PatternJson = when (this) {
    is QueuePattern.Goto -> PatternJson.Goto(point.toJson())
    is QueuePattern.Circle -> PatternJson.Circle(center.toJson(), radius.meters)
    is QueuePattern.Segment -> PatternJson.Segment(from.toJson(), to.toJson())
    is QueuePattern.Path -> PatternJson.Path(points.map { it.toJson() })
    is QueuePattern.Survey -> PatternJson.Survey(start.toJson(), length.meters, width.meters, spacing.meters, direction.name)
    QueuePattern.Hold -> PatternJson.Hold
    QueuePattern.Land -> PatternJson.Land
    QueuePattern.ReturnHome -> PatternJson.ReturnHome
}

/** [QueueElement] as JSON; a duration of zero or less (none) is written as null. */
internal fun QueueElement.toJson(): ElementJson = ElementJson(pattern.toJson(), limit?.seconds(), altitude?.meters)

/** [QueueEntry] as JSON. */
internal fun QueueEntry.toJson(): EntryJson = EntryJson(id, element.toJson())

/** [QueueStatus] as JSON. */
internal fun QueueStatus.toJson(): StatusJson = StatusJson(current?.toJson(), remaining?.seconds(), pending.map { it.toJson() })

/** The core point; throws [IllegalArgumentException] with the core's message when it is out of range. */
internal fun PointJson.toPoint(): QueuePoint = when (this) {
    is PointJson.Local -> QueuePoint.Local(north.m, east.m)
    is PointJson.Global -> QueuePoint.Global(Location(lat, lon, 0.m))
}

/** The core pattern; throws [IllegalArgumentException] with the core's message for a bad one (radius 0, no points…). */
internal fun PatternJson.toPattern(): QueuePattern = when (this) {
    is PatternJson.Goto -> QueuePattern.Goto(point.toPoint())
    is PatternJson.Circle -> QueuePattern.Circle(center.toPoint(), radius.m)
    is PatternJson.Segment -> QueuePattern.Segment(from.toPoint(), to.toPoint())
    is PatternJson.Path -> QueuePattern.Path(points.map { it.toPoint() })
    is PatternJson.Survey -> {
        val heading = SurveyDirection.entries.firstOrNull { it.name == direction }
            ?: throw IllegalArgumentException("survey direction must be one of ${SurveyDirection.entries.joinToString()}, was $direction")
        QueuePattern.Survey(start.toPoint(), length.m, width.m, spacing.m, heading)
    }
    PatternJson.Hold -> QueuePattern.Hold
    PatternJson.Land -> QueuePattern.Land
    PatternJson.ReturnHome -> QueuePattern.ReturnHome
}

/** The core element; throws [IllegalArgumentException] with the core's message for a bad one. */
internal fun ElementJson.toElement(): QueueElement {
    val duration = durationS?.let {
        require(it.isFinite()) { "duration must be a finite number of seconds, was $it" }
        (it * 1000).roundToLong().milliseconds
    }
    return QueueElement(pattern.toPattern(), duration, altM?.m)
}

/** "#3 circle (0 N, 50 E) r 30 m clockwise at 25 m for 30 s": an entry for people. */
internal fun EntryJson.describe(): String = "#$id ${element.describe()}"

/** An element for people: its pattern, then its height and duration when it has them. */
internal fun ElementJson.describe(): String = buildString {
    append(pattern.describe())
    altM?.let { append(" at ").append(it.plain()).append(" m") }
    durationS?.let { append(" for ").append(it.plain()).append(" s") }
}

private fun PatternJson.describe(): String = when (this) {
    is PatternJson.Goto -> "goto ${point.describe()}"
    is PatternJson.Circle -> "circle ${center.describe()} r ${kotlin.math.abs(radius).plain()} m ${if (radius > 0) "clockwise" else "counter-clockwise"}"
    is PatternJson.Segment -> "segment ${from.describe()} → ${to.describe()}"
    is PatternJson.Path -> "path " + points.joinToString(" → ") { it.describe() }
    is PatternJson.Survey -> "survey ${length.plain()} × ${width.plain()} m from ${start.describe()} toward ${direction.lowercase().replace('_', '-')}, tracks ${spacing.plain()} m apart"
    PatternJson.Hold -> "hold"
    PatternJson.Land -> "land"
    PatternJson.ReturnHome -> "return home"
}

private fun PointJson.describe(): String = when (this) {
    is PointJson.Local -> "(${north.plain()} N, ${east.plain()} E)"
    is PointJson.Global -> "($lat, $lon)"
}

/** 30 rather than 30.0; 12.5 as it is. */
internal fun Double.plain(): String = if (this == floor(this) && kotlin.math.abs(this) < 1e15) toLong().toString() else toString()

private fun Duration.seconds(): Double = inWholeMilliseconds / 1000.0
