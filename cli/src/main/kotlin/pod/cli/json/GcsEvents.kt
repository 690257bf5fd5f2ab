package pod.cli.json

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable

// The events only `pod gcs` sends, to the page over its WebSocket; the others it sends are the
// ones every `--json` command prints (found, telemetry, task_started…), unchanged.

/** The first message a page gets: what it is looking at. [tiles] is the `--tiles` URL template, null for the offline grid. */
@Serializable @SerialName("gcs_hello")
public data class GcsHello(
    val source: String,
    val tiles: String?,
    @SerialName("time_scale") val timeScale: Double,
    /** The largest number of batches the page gets per second. */
    @SerialName("batches_per_s") val batchesPerSecond: Int,
) : Event

/** What happened since the page's last batch, in order: at most one batch per tick ([GcsHello.batchesPerSecond] a second). */
@Serializable @SerialName("gcs_batch")
public data class GcsBatch(
    /** This batch's number on this page, from 1. */
    val seq: Long,
    val events: List<Event>,
) : Event

/**
 * The answer to the page's request [id]: [ok] when the vehicle did it, else [error] says why (the
 * vehicle's refusal and its reason, a bad argument, a lost vehicle). [detail] is what an answer
 * carries beyond ok (a downloaded plan, a queue entry), as JSON text or words.
 */
@Serializable @SerialName("reply")
public data class Reply(val id: Long, val ok: Boolean, val error: String? = null, val detail: String? = null) : Event

/** A vehicle's home, as it last reported it (HOME_POSITION). */
@Serializable @SerialName("home")
public data class Home(val sysid: Int, val lat: Finite, val lon: Finite, @SerialName("alt_msl") val altMsl: Finite?) : Event

/**
 * What the fleet table shows beyond telemetry: [awaiting] what the vehicle has not answered yet
 * (null: nothing), [text] its last STATUSTEXT and [severity] that text's (MAVLink's name, e.g. WARNING).
 */
@Serializable @SerialName("vehicle_status")
public data class VehicleStatus(val sysid: Int, val awaiting: String?, val text: String?, val severity: String?) : Event

/** A STATUSTEXT vehicle [sysid] sent: [severity] is MAVLink's name (WARNING, INFO…). */
@Serializable @SerialName("vehicle_text")
public data class VehicleText(val sysid: Int, val severity: String, val text: String) : Event
