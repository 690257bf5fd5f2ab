package pod.cli.json

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable

// The events `pod gcs` logs for what its pages did to a vehicle and its queue: every open page
// sees them in its event log, so two operators at two browsers see each other's commands.

/**
 * A page asked vehicle [sysid] to do [action] (`arm`, `takeoff 20 m`, `mode LAND`, `queue append
 * goto …`). [outcome] is `asked` when the request arrived, then `ok` or `failed` when the vehicle
 * answered; [detail] is what it answered (the refusal and its reason when `failed`).
 */
@Serializable @SerialName("page_action")
public data class PageAction(val sysid: Int, val action: String, val outcome: String, val detail: String? = null) : Event

/**
 * Whether the ground station is flying vehicle [sysid]'s mission queue ([flying]); when a flight
 * ended by itself, [error] says why (the element refused, the vehicle lost, not flying), else null.
 */
@Serializable @SerialName("queue_flight")
public data class QueueFlightState(val sysid: Int, val flying: Boolean, val error: String?) : Event
