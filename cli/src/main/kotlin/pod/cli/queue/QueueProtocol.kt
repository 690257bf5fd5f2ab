package pod.cli.queue

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import kotlinx.serialization.json.Json
import pod.cli.json.Finite
import pod.core.queue.InsertMode

/*
 * The control protocol between `pod queue serve` (the host, which holds the queue and flies it) and
 * the one-shot `pod queue …` commands (clients):
 *
 * - TCP on a loopback address only (default 127.0.0.1:14660): the queue steers a vehicle, so
 *   nobody off this machine may change it.
 * - UTF-8 JSON, one object per line. A client sends a [QueueRequest] line; the host answers each with
 *   one [QueueResponse] line, in order. A connection may carry any number of requests; the CLI's
 *   clients send one and close.
 * - Request kinds (field `type`): `insert` {mode, element}, `next`, `clear`, `status`. Every
 *   response carries the queue's status after the request and the vehicle's state; `insert` also
 *   the new entry (with its id), `next` the entry it ended.
 * - A request the host cannot read or apply gets `ok: false` and an `error` message; the
 *   connection stays open. A line longer than [QueueProtocol.MAX_LINE] characters closes it.
 *
 *   > {"type":"insert","mode":"append","element":{"pattern":{"type":"goto","point":{"type":"local","north":30.0,"east":0.0}},"duration_s":null,"alt_m":null}}
 *   < {"ok":true,"error":null,"entry":{"id":1,"element":{…}},"ended":null,"status":{"current":{…},"remaining_s":null,"pending":[]},"vehicle":{…}}
 */

/** A Paparazzi insertion mode as the protocol and the `pod queue` subcommands name it. */
@Serializable
public enum class Insertion(
    /** The queue's mode. */
    public val mode: InsertMode,
    /** The `pod queue` subcommand. */
    public val command: String,
    /** What the command did, for people ("appended"). */
    public val done: String,
) {
    @SerialName("append") APPEND(InsertMode.APPEND, "append", "appended"),
    @SerialName("prepend") PREPEND(InsertMode.PREPEND, "prepend", "prepended"),
    @SerialName("replace_current") REPLACE_CURRENT(InsertMode.REPLACE_CURRENT, "replace", "replaced the current element with"),
    @SerialName("replace_all") REPLACE_ALL(InsertMode.REPLACE_ALL, "replace-all", "replaced the whole queue with"),
}

/** What a client asks of the host. */
@Serializable
public sealed interface QueueRequest {
    /** Insert [element] by [mode]. */
    @Serializable @SerialName("insert")
    public data class Insert(val mode: Insertion, val element: ElementJson) : QueueRequest

    /** End the current element now. */
    @Serializable @SerialName("next")
    public data object Next : QueueRequest

    /** Empty the queue; the vehicle holds where it is. */
    @Serializable @SerialName("clear")
    public data object Clear : QueueRequest

    /** Only the status. */
    @Serializable @SerialName("status")
    public data object Status : QueueRequest
}

/** The vehicle a host flies, as it last reported: [sysid], [mode], [armed], height above home. */
@Serializable
public data class VehicleJson(
    val sysid: Int,
    val mode: String?,
    val armed: Boolean,
    @SerialName("relative_alt_m") val relativeAltM: Finite?,
)

/**
 * The host's answer: [ok], or the [error] that kept it from doing what was asked. [entry] is the
 * entry an `insert` made; [ended] the entry a `next` ended (null when the queue was empty);
 * [status] the queue after the request; [vehicle] the vehicle that flies it.
 */
@Serializable
public data class QueueResponse(
    val ok: Boolean,
    val error: String? = null,
    val entry: EntryJson? = null,
    val ended: EntryJson? = null,
    val status: StatusJson? = null,
    val vehicle: VehicleJson? = null,
)

/** Encodes and decodes the protocol's lines. */
internal object QueueProtocol {
    /** The port `pod queue serve` listens on and the clients talk to unless told otherwise. */
    const val DEFAULT_PORT = 14660

    /** The longest line either side reads (a 1000-point path fits many times over). */
    const val MAX_LINE = 1 shl 20

    private val json = Json {
        classDiscriminator = "type"
        encodeDefaults = true
        explicitNulls = true
        // A newer peer may add fields; the ones both know keep their meaning.
        ignoreUnknownKeys = true
    }

    fun encode(request: QueueRequest): String = json.encodeToString(QueueRequest.serializer(), request)

    fun encode(response: QueueResponse): String = json.encodeToString(QueueResponse.serializer(), response)

    /** Throws [kotlinx.serialization.SerializationException] (an [IllegalArgumentException]) for a line that is not a request. */
    fun decodeRequest(line: String): QueueRequest = json.decodeFromString(QueueRequest.serializer(), line)

    /** Throws [kotlinx.serialization.SerializationException] (an [IllegalArgumentException]) for a line that is not a response. */
    fun decodeResponse(line: String): QueueResponse = json.decodeFromString(QueueResponse.serializer(), line)
}
