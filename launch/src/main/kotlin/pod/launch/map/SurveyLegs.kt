package pod.launch.map

import pod.core.survey.SurveyWaypoint
import pod.core.units.Location

/**
 * The path through [waypoints] cut into runs of legs of one kind: photographed (along a track,
 * between its start and end) or not (turnaround extensions, transits, the turn to the next
 * track). Neighbouring runs share their joining waypoint.
 */
internal fun surveyLegs(waypoints: List<SurveyWaypoint>): List<Pair<Boolean, List<Location>>> {
    val runs = mutableListOf<Pair<Boolean, MutableList<Location>>>()
    for (i in 0 until waypoints.size - 1) {
        val a = waypoints[i]
        val b = waypoints[i + 1]
        val photographed = a.onTrack() && b.onTrack() && a.track == b.track && !a.trackEnd
        if (runs.lastOrNull()?.first != photographed) runs += photographed to mutableListOf(a.location)
        runs.last().second += b.location
    }
    return runs
}

private fun SurveyWaypoint.onTrack() = !turnaround && !transit
