package pod.mavlink.mission

/**
 * The mission protocol's messages, reduced to what the protocol machines need: no addresses, no
 * io.dronefleet builders. [MissionWire] translates them to and from MAVLink messages, so the
 * machines stay pure and property tests can generate and drop them cheaply.
 */
public sealed class MissionMessage {
    /** MISSION_COUNT: the sender has (upload) or holds (download answer) [count] items. */
    public data class Count(val type: MissionType, val count: Int) : MissionMessage()

    /** MISSION_REQUEST_LIST: send me your count. */
    public data class RequestList(val type: MissionType) : MissionMessage()

    /** MISSION_REQUEST_INT, or the legacy MISSION_REQUEST when [legacy] (both are answered with MISSION_ITEM_INT). */
    public data class Request(val type: MissionType, val seq: Int, val legacy: Boolean = false) : MissionMessage()

    /**
     * MISSION_ITEM_INT, or the legacy MISSION_ITEM (latitude and longitude as float degrees) when
     * [legacy]; [item] holds wire integers either way (see [MissionWire]).
     */
    public data class Item(val item: MissionItem, val legacy: Boolean = false) : MissionMessage()

    /** MISSION_ACK. */
    public data class Ack(val type: MissionType, val result: MissionResult) : MissionMessage()

    /** MISSION_CLEAR_ALL. */
    public data class ClearAll(val type: MissionType) : MissionMessage()

    /** MISSION_WRITE_PARTIAL_LIST: replace items [start]..[end] (inclusive). */
    public data class WritePartial(val type: MissionType, val start: Int, val end: Int) : MissionMessage()

    /** MISSION_SET_CURRENT. */
    public data class SetCurrent(val seq: Int) : MissionMessage()

    /** MISSION_CURRENT: the item being executed, of [total]. */
    public data class Current(val seq: Int, val total: Int) : MissionMessage()
}
