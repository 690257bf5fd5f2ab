package pod.mavlink.mission

/**
 * The mission protocol's messages, reduced to what the protocol machines need: no addresses, no
 * io.dronefleet builders. [MissionWire] translates them to and from MAVLink messages, so the
 * machines stay pure and property tests can generate and drop them cheaply.
 */
public sealed class MissionMessage {
    /**
     * MISSION_COUNT: the sender has (upload) or holds (download answer) [count] items.
     *
     * @property type which list (mission, fence or rally points) the message is about.
     * @property count how many items the list has.
     */
    public data class Count(val type: MissionType, val count: Int) : MissionMessage()

    /**
     * MISSION_REQUEST_LIST: send me your count.
     *
     * @property type which list (mission, fence or rally points) the message is about.
     */
    public data class RequestList(val type: MissionType) : MissionMessage()

    /**
     * MISSION_REQUEST_INT, or the legacy MISSION_REQUEST when [legacy] (both are answered with MISSION_ITEM_INT).
     *
     * @property type which list (mission, fence or rally points) the message is about.
     * @property seq the index of the item asked for, from 0.
     * @property legacy true when it came as the deprecated MISSION_REQUEST.
     */
    public data class Request(val type: MissionType, val seq: Int, val legacy: Boolean = false) : MissionMessage()

    /**
     * MISSION_ITEM_INT, or the legacy MISSION_ITEM (latitude and longitude as float degrees) when
     * [legacy]; [item] holds wire integers either way (see [MissionWire]).
     *
     * @property item the item, its position and mission type included.
     * @property legacy true for the float MISSION_ITEM form.
     */
    public data class Item(val item: MissionItem, val legacy: Boolean = false) : MissionMessage()

    /**
     * MISSION_ACK: the end of a transfer, or its refusal.
     *
     * @property type which list (mission, fence or rally points) the message is about.
     * @property result accepted, or why not.
     */
    public data class Ack(val type: MissionType, val result: MissionResult) : MissionMessage()

    /**
     * MISSION_CLEAR_ALL: delete the list on the vehicle.
     *
     * @property type which list (mission, fence or rally points) the message is about.
     */
    public data class ClearAll(val type: MissionType) : MissionMessage()

    /**
     * MISSION_WRITE_PARTIAL_LIST: replace items [start]..[end] (inclusive).
     *
     * @property type which list (mission, fence or rally points) the message is about.
     * @property start the index of the first item replaced.
     * @property end the index of the last item replaced.
     */
    public data class WritePartial(val type: MissionType, val start: Int, val end: Int) : MissionMessage()

    /**
     * MISSION_SET_CURRENT: make another item the one being executed.
     *
     * @property seq the index of the item to execute next.
     */
    public data class SetCurrent(val seq: Int) : MissionMessage()

    /**
     * MISSION_CURRENT: the item being executed, of [total].
     *
     * @property seq the index of the item being executed.
     * @property total how many items the mission has; 0 from a sender that leaves out this MAVLink 2 extension field.
     */
    public data class Current(val seq: Int, val total: Int) : MissionMessage()
}
