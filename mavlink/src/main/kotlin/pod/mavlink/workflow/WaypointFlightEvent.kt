package pod.mavlink.workflow

import pod.core.workflow.WaypointRecord

/** What a [WaypointFlight.flight] tells as it flies. */
public sealed interface WaypointFlightEvent<out R> {
    /**
     * The vehicle heads for [waypoint] or, when [holding], holds for a pause there.
     *
     * @property waypoint the index into the flight's waypoints.
     * @property holding true while it holds for a pause; false when it flies (on again).
     */
    public data class Progress(val waypoint: Int, val holding: Boolean) : WaypointFlightEvent<Nothing>

    /**
     * The flight is done: a record per waypoint, in order. Always the last event.
     *
     * @property records one record per waypoint, in the order flown.
     */
    public data class Finished<R>(val records: List<WaypointRecord<R>>) : WaypointFlightEvent<R>
}
