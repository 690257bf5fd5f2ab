package pod.launch

import pod.core.survey.SurveyPlan
import pod.core.units.Location
import pod.launch.map.SvgMap

/**
 * What a map of one survey run shows: the surveyed [polygon], the forward path [plan], the plan
 * waypoints whose photo detected something ([forwardFlagged]), the backward mission's visits
 * ([backwardOrder], in the order flown), objects on the ground where known ([objects]: a
 * simulation's seeded objects, say) and the track the vehicle flew ([track]).
 *
 * Waypoints are named by their index in [SurveyPlan.waypoints], so the picture stays independent
 * of how a run recorded them; any index outside the plan is refused at construction.
 */
public class SurveyPicture(
    /** The surveyed polygon's vertices (at least 3, not closed). */
    public val polygon: List<Location>,
    /** The planned forward path. */
    public val plan: SurveyPlan,
    /** Indices into [plan]'s waypoints whose photo detected something, each at most once. */
    public val forwardFlagged: List<Int>,
    /** Indices into [plan]'s waypoints that the backward mission visited, in the order flown. */
    public val backwardOrder: List<Int>,
    /** The name of the vehicle that flew the survey, shown in the legend beside its track. */
    public val vehicleName: String,
    /** Where objects on the ground are known to lie; empty when unknown. */
    public val objects: List<Location> = emptyList(),
    /** The vehicle's flown track, forward and backward; empty when not recorded. */
    public val track: List<Location> = emptyList(),
    /** The vehicle's system id, which picks its colour the same way as on [svg]'s fleet maps. */
    public val vehicleId: Int = 1,
) {
    init {
        require(polygon.size >= 3) { "polygon must have at least 3 points, was ${polygon.size}" }
        val indices = plan.waypoints.indices
        forwardFlagged.firstOrNull { it !in indices }?.let {
            throw IllegalArgumentException("forwardFlagged must index the plan's waypoints 0..${indices.last}, was $it")
        }
        require(forwardFlagged.toSet().size == forwardFlagged.size) { "forwardFlagged must not repeat a waypoint, was $forwardFlagged" }
        backwardOrder.firstOrNull { it !in indices }?.let {
            throw IllegalArgumentException("backwardOrder must index the plan's waypoints 0..${indices.last}, was $it")
        }
    }
}

/**
 * The SVG map of [picture] under [title]: the polygon shaded, the forward path (photographed
 * tracks solid, turnaround and transit legs dotted, a dot per photo waypoint), the flown track in
 * the vehicle's colour, a ring on each flagged waypoint, a cross on each known object, and the
 * backward path in its own colour with its stops numbered 1, 2, … in the order flown; a legend
 * names each layer and the canvas is fitted to all of it. Each layer is an SVG group with an id
 * (`survey-area`, `forward-path`, `photo-waypoints`, `flown`, `detections`, `objects`,
 * `backward-path`, `legend`).
 */
public fun surveySvg(picture: SurveyPicture, title: String): String {
    val map = SvgMap()
    map.surveyArea(picture.polygon)
    map.forwardPath(picture.plan)
    map.flown(picture.vehicleId, picture.vehicleName, picture.track)
    map.objects(picture.objects)
    map.detections(picture.plan, picture.forwardFlagged)
    map.backwardPath(picture.plan, picture.backwardOrder)
    return map.render(title)
}
