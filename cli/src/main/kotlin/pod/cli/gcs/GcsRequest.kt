package pod.cli.gcs

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable

/**
 * A page's request: a JSON object whose `op` field names the kind and whose `id` the page picks to
 * match the [pod.cli.json.Reply] it gets back. Each kind carries itself out in [answer]; the kinds
 * live beside the page feature they serve (VehicleRequests, QueueRequests, SurveyRequests…), all in
 * this package, as one sealed family read by [GcsRequests.decode].
 */
@Serializable
public sealed interface GcsRequest {
    /** The page's number for this request, echoed in the reply. */
    public val id: Long

    /**
     * Carries the request out on [fleet] and returns the reply's detail (null: just ok). Throws
     * [GcsRequestException], a [pod.core.PodException] (a vehicle's refusal, a lost vehicle) or an
     * [IllegalArgumentException] (a bad argument) whose message becomes the reply's error.
     */
    public suspend fun answer(fleet: GcsFleet): String?
}

/** `{"op":"ping","id":1}`: answered "pong" at once; the page's check that its requests get through. */
@Serializable @SerialName("ping")
public data class Ping(override val id: Long) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String = "pong"
}
