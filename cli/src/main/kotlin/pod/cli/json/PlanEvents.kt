package pod.cli.json

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable

// The events of the ground station's plans panel (`pod gcs`): a plan file going to a vehicle, how
// it went, and the lists a vehicle holds as the map draws them; and where a program's page is served.

/**
 * A plan transfer of vehicle [sysid] under way: [file] (the page's file name, or `its plan` for a
 * download), [list] the list moving now (mission, fence, rally), [done] of [total] items.
 * [waiting] says why it has not started yet, when the vehicle makes it wait (an abandoned upload
 * still held). [finished] is set on the last one, and [failed] too when it did not go through.
 */
@Serializable @SerialName("plan_progress")
public data class PlanProgress(
    val sysid: Int,
    val file: String,
    val action: String,
    val list: String,
    val done: Int,
    val total: Int,
    val waiting: String? = null,
    val finished: Boolean = false,
    val failed: Boolean = false,
) : Event

/**
 * How a plan transfer of vehicle [sysid] ended, for the event log: [ok], else [error] in the
 * vehicle's words (or what is wrong with [file]); [items] per list that went (`mission` → 12).
 */
@Serializable @SerialName("plan_transfer")
public data class PlanTransfer(
    val sysid: Int,
    val file: String,
    val action: String,
    val ok: Boolean,
    val error: String? = null,
    val items: Map<String, Int> = emptyMap(),
) : Event

/** A waypoint of a mission on board: [n] its number as a planner shows it (1 = the first item after home). */
@Serializable
public data class OnBoardItem(
    val seq: Int,
    val n: Int,
    val command: Int,
    val lat: Finite,
    val lon: Finite,
    val alt: Finite?,
    /** A navigation command (the path joins these); false for one that only names a place (a region of interest). */
    val nav: Boolean,
)

/** A fence polygon on board: the vehicle must stay in it ([inclusion]) or out of it; [points] as `[lat, lon]`. */
@Serializable
public data class OnBoardPolygon(val inclusion: Boolean, val points: List<List<Finite>>)

/** A fence circle on board, [radius] in metres. */
@Serializable
public data class OnBoardCircle(val inclusion: Boolean, val lat: Finite, val lon: Finite, val radius: Finite)

/** A rally point on board, [alt] above home. */
@Serializable
public data class OnBoardRally(val lat: Finite, val lon: Finite, val alt: Finite?)

/**
 * What vehicle [sysid] holds, as last downloaded: the mission's positioned items, the fence and
 * the rally points; [home] the plan's home (ArduPilot's item 0, else the vehicle's HOME_POSITION).
 */
@Serializable @SerialName("on_board")
public data class OnBoard(
    val sysid: Int,
    val mission: List<OnBoardItem>,
    val polygons: List<OnBoardPolygon>,
    val circles: List<OnBoardCircle>,
    val rally: List<OnBoardRally>,
    val home: List<Finite>?,
    /** Items in the mission list, positioned or not (a DO_ command has none). */
    @SerialName("mission_items") val missionItems: Int,
) : Event

/** The ground station's page for a running program (`pod demo --gcs`, `pod run --gcs`) is served at [url]. */
@Serializable @SerialName("gcs_serving")
public data class GcsServing(val url: String) : Event
