package pod.mavlink.workflow

import pod.core.workflow.WaypointRecord

/** What a [WaypointFlight.flight] tells as it flies. */
public sealed interface WaypointFlightEvent<out R> {
    /** The vehicle heads for [waypoint] (an index into the flight's waypoints) or, when [holding], holds for a pause there. */
    public data class Progress(val waypoint: Int, val holding: Boolean) : WaypointFlightEvent<Nothing>

    /** The flight is done: a record per waypoint, in order. Always the last event. */
    public data class Finished<R>(val records: List<WaypointRecord<R>>) : WaypointFlightEvent<R>
}
