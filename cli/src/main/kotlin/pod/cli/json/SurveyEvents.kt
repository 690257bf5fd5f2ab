package pod.cli.json

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable

// The survey mission control of `pod gcs` (the I-Seed operator's app), as the page sees it: the
// app's state, the path built, the operator's commands and the flight's reports with their event
// ids, the forward pass's photos and the backward pass's route and measurements.

/**
 * The survey app's state for vehicle [sysid]: [phase] is `waiting`, `ready`, `path_built`,
 * `executing`, `paused`, `finished` or `aborted`; while executing or paused, [pass] (`forward`,
 * `backward`, `home`) and the [waypoint] (index into that pass, null before the first); [reason]
 * why it was aborted. [eventId] is the latest command's event id the state reflects; [run] the
 * event id of the start of the flight its photos belong to (0: none yet).
 */
@Serializable @SerialName("survey_state")
public data class SurveyState(
    val sysid: Int,
    val phase: String,
    val pass: String?,
    val waypoint: Int?,
    val reason: String?,
    @SerialName("event_id") val eventId: Long,
    val run: Long,
) : Event

/** A point of a survey drawn on the map. */
@Serializable
public data class SurveyPoint(val lat: Finite, val lon: Finite)

/** A waypoint of a planned survey path: where, and whether a photo is taken there. */
@Serializable
public data class SurveyPathPoint(val lat: Finite, val lon: Finite, val photo: Boolean)

/**
 * A survey path planned for vehicle [sysid] over the operator's [polygon]: its [waypoints] in
 * flying order at [heightM] above home, [tracks] tracks [spacingM] apart, [lengthM] long, over
 * [areaM2]. [eventId] is the build command's (0: only planned, not built). Sent when a path is
 * built, and as the answer to `survey_plan`.
 */
@Serializable @SerialName("survey_path")
public data class SurveyPath(
    val sysid: Int,
    @SerialName("event_id") val eventId: Long,
    val polygon: List<SurveyPoint>,
    val waypoints: List<SurveyPathPoint>,
    @SerialName("height_m") val heightM: Finite,
    val tracks: Int,
    @SerialName("spacing_m") val spacingM: Finite,
    @SerialName("length_m") val lengthM: Finite,
    @SerialName("area_m2") val areaM2: Finite,
) : Event

/**
 * The operator's [command] (`build`, `cancel_path`, `start`, `pause`, `resume`, `abort`) to the
 * survey of vehicle [sysid] with its [eventId]: [accepted], or refused for [reason].
 */
@Serializable @SerialName("survey_command")
public data class SurveyOperatorCommand(
    val sysid: Int,
    val command: String,
    @SerialName("event_id") val eventId: Long,
    val accepted: Boolean,
    val reason: String?,
) : Event

/**
 * What the flight of vehicle [sysid] reported ([report]: `vehicle` (with [ready]), `flying`,
 * `holding`, `done`, `stopped` (with [reason])), stamped with the [eventId] of the latest command it
 * had applied; [counted] is false when the app ignored it as older than its last command. Each
 * report is sent once, though the flight repeats it.
 */
@Serializable @SerialName("survey_report")
public data class SurveyReport(
    val sysid: Int,
    val report: String,
    val pass: String?,
    val waypoint: Int?,
    val ready: Boolean?,
    val reason: String?,
    @SerialName("event_id") val eventId: Long,
    val counted: Boolean,
) : Event

/**
 * A photo of the forward pass of run [run] on vehicle [sysid], at the plan's [waypoint], taken at
 * [lat], [lon]: the simulator's [objects] it detected (empty: none, or a camera that says nothing
 * of what it saw), and whether that [flagged] the waypoint for the backward pass. [taken] is false
 * when the vehicle reported no photo in time.
 */
@Serializable @SerialName("survey_photo")
public data class SurveyPhoto(
    val sysid: Int,
    val run: Long,
    val waypoint: Int,
    val lat: Finite,
    val lon: Finite,
    val objects: List<Int>,
    val flagged: Boolean,
    val taken: Boolean,
) : Event

/**
 * The backward pass of run [run] on vehicle [sysid]: the flagged waypoints (the plan's indices) in
 * the [order] it flies them, planned as it begins, and those already [measured], in the order flown.
 */
@Serializable @SerialName("survey_backward")
public data class SurveyBackward(
    val sysid: Int,
    val run: Long,
    val order: List<Int>,
    val measured: List<SurveyMeasured>,
) : Event

/** A waypoint the backward pass visited (the plan's index) and the range measured there (null: none). */
@Serializable
public data class SurveyMeasured(val waypoint: Int, @SerialName("range_m") val rangeM: Finite?)
