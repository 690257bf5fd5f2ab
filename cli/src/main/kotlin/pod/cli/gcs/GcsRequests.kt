package pod.cli.gcs

import kotlinx.coroutines.CancellationException
import kotlinx.serialization.SerializationException
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import kotlinx.serialization.json.longOrNull
import pod.cli.json.Reply
import pod.core.PodException

/** Reads a page's requests and turns how each went into its [Reply]. */
public object GcsRequests {
    private val json = Json { classDiscriminator = "op" }

    /** The request in [text]; a [GcsRequestException] naming what is wrong when it is not one. */
    public fun decode(text: String): GcsRequest = try {
        json.decodeFromString(GcsRequest.serializer(), text)
    } catch (e: SerializationException) {
        throw GcsRequestException("not a request: ${e.message?.lineSequence()?.first()}")
    } catch (e: IllegalArgumentException) {
        throw GcsRequestException("not a request: ${e.message?.lineSequence()?.first()}")
    }

    /** [request] as the page sends it (tests and tools speak to the server as a page does). */
    public fun encode(request: GcsRequest): String = json.encodeToString(GcsRequest.serializer(), request)

    /** The `id` of [text] when it has one, so that even a malformed request gets a reply it can match; -1 otherwise. */
    public fun idOf(text: String): Long =
        runCatching { json.parseToJsonElement(text).jsonObject["id"]?.jsonPrimitive?.longOrNull }.getOrNull() ?: -1

    /**
     * Answers the page's [text] on [fleet]: the reply to send back, never an exception (a
     * cancellation still propagates). Errors Pod foresees (a refusal, a lost vehicle, a bad
     * argument) are said in its words; anything else as "internal error".
     */
    public suspend fun answer(fleet: GcsFleet, text: String): Reply = answer(text) { it.answer(fleet) }

    /** [answer] with the decoded request carried out by [carryOut] (tests give their own). */
    internal suspend fun answer(text: String, carryOut: suspend (GcsRequest) -> String?): Reply {
        val id = idOf(text)
        return try {
            val request = decode(text)
            Reply(request.id, ok = true, detail = carryOut(request))
        } catch (e: CancellationException) {
            throw e
        } catch (e: GcsRequestException) {
            Reply(id, ok = false, error = e.message)
        } catch (e: PodException) {
            Reply(id, ok = false, error = e.message ?: e::class.simpleName)
        } catch (e: IllegalArgumentException) {
            Reply(id, ok = false, error = e.message ?: "bad argument")
        } catch (e: Exception) {
            Reply(id, ok = false, error = "internal error: ${e::class.simpleName}: ${e.message}")
        }
    }
}
