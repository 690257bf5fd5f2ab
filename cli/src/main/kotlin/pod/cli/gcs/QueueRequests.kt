package pod.cli.gcs

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import kotlinx.serialization.json.Json
import pod.cli.queue.ElementJson
import pod.cli.queue.EntryJson
import pod.cli.queue.PatternJson
import pod.cli.queue.describe
import pod.cli.queue.toElement
import pod.cli.queue.toJson
import pod.core.queue.InsertMode
import pod.mavlink.queue.QueueFlightConfig
import kotlin.math.PI
import kotlin.math.abs

// The mission-queue panel's requests, on the fleet's QueueDesk. Elements are `pod queue`'s JSON
// (pod.cli.queue.ElementJson: a goto, a circle with a signed radius, a path…), so what a page adds
// reads the same as what `pod queue append --json` prints.

private val wire = Json { encodeDefaults = true }

/**
 * `{"op":"queue_insert","id":7,"sysid":1,"mode":"append","element":{"pattern":{"type":"goto","point":{"type":"global","lat":…,"lon":…}},"alt_m":20}}`:
 * adds [element] to vehicle [sysid]'s queue by [mode] (`append`, `prepend`, `replace_current`,
 * `replace_all`) and flies the queue. A circle may give [turns] instead of a duration: it is
 * flown for that many times round at the speed a queue circles at. The reply's detail is the new
 * entry as JSON ([EntryJson]).
 */
@Serializable @SerialName("queue_insert")
public data class QueueInsert(
    override val id: Long,
    val sysid: Int,
    val mode: String,
    val element: ElementJson,
    val turns: Double? = null,
) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String {
        val how = INSERT_MODES[mode] ?: throw IllegalArgumentException("mode must be one of ${INSERT_MODES.keys.joinToString()}, was $mode")
        val asking = withTurns()
        val asked = asking.toElement()
        return pageAction(fleet, sysid, "queue $mode ${asking.describe()}") {
            wire.encodeToString(EntryJson.serializer(), fleet.queues.insert(sysid, how, asked).toJson())
        }.orEmpty()
    }

    /** [element] with [turns] turned into its duration: turns × 2π|r| ÷ the circling speed. */
    internal fun withTurns(): ElementJson {
        val n = turns ?: return element
        val circle = element.pattern as? PatternJson.Circle ?: throw IllegalArgumentException("turns are for a circle, not a ${element.pattern::class.simpleName?.lowercase()}")
        require(element.durationS == null) { "give a circle turns or a duration, not both" }
        require(n > 0 && n <= MAX_TURNS) { "turns must be in (0, $MAX_TURNS], was $n" }
        return element.copy(durationS = n * 2 * PI * abs(circle.radius) / QueueFlightConfig().circleSpeed)
    }

    private companion object {
        const val MAX_TURNS = 1000.0
        val INSERT_MODES = mapOf(
            "append" to InsertMode.APPEND, "prepend" to InsertMode.PREPEND,
            "replace_current" to InsertMode.REPLACE_CURRENT, "replace_all" to InsertMode.REPLACE_ALL,
        )
    }
}

/** Ends the current element of vehicle [sysid]'s queue; the detail is the entry it ended as JSON, or "the queue was empty". */
@Serializable @SerialName("queue_next")
public data class QueueNext(override val id: Long, val sysid: Int) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String = pageAction(fleet, sysid, "queue next") {
        fleet.queues.queue(sysid).next()?.let { wire.encodeToString(EntryJson.serializer(), it.toJson()) } ?: "the queue was empty"
    }.orEmpty()
}

/** Empties vehicle [sysid]'s queue; the vehicle holds where it is. */
@Serializable @SerialName("queue_clear")
public data class QueueClear(override val id: Long, val sysid: Int) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String? = pageAction(fleet, sysid, "queue clear") {
        fleet.queues.queue(sysid).clear()
        "cleared: holding"
    }
}
