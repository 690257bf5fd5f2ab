package pod.mavlink.plan

import pod.mavlink.MavFrames
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import kotlin.math.roundToInt

/**
 * The fence and rally lists of a plan as a vehicle stores them (MAV_MISSION_TYPE_FENCE / _RALLY), and back.
 *
 * Encoding from MAVLink's common.xml: MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION (5001) / _EXCLUSION (5002), one
 * item per vertex with param1 = the polygon's vertex count; MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION (5003) /
 * _EXCLUSION (5004) with param1 = radius in metres; MAV_CMD_NAV_RALLY_POINT (5100) with z = altitude. Frames as
 * QGC sends them (mavlink/qgroundcontrol `GeoFenceManager` / `RallyPointManager` via `PlanManager`): fence items
 * in MAV_FRAME_GLOBAL, rally points in MAV_FRAME_GLOBAL_RELATIVE_ALT. Positions travel as degrees × 10⁷, so a
 * fence that went to a vehicle comes back rounded to 10⁻⁷° and radii to Float.
 */
public object PlanLists {
    /** MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION. */
    public const val FENCE_POLYGON_INCLUSION: Int = 5001

    /** MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION. */
    public const val FENCE_POLYGON_EXCLUSION: Int = 5002

    /** MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION. */
    public const val FENCE_CIRCLE_INCLUSION: Int = 5003

    /** MAV_CMD_NAV_FENCE_CIRCLE_EXCLUSION. */
    public const val FENCE_CIRCLE_EXCLUSION: Int = 5004

    /** MAV_CMD_NAV_RALLY_POINT. */
    public const val RALLY_POINT: Int = 5100

    /** The FENCE list of [fence]: polygons first (one item per vertex), then circles, seq from 0. */
    public fun fenceItems(fence: PlanGeoFence): List<MissionItem> {
        val items = mutableListOf<MissionItem>()
        fence.polygons.forEach { polygon ->
            val command = if (polygon.inclusion) FENCE_POLYGON_INCLUSION else FENCE_POLYGON_EXCLUSION
            polygon.vertices.forEach { vertex ->
                items += fenceItem(items.size, command, polygon.vertices.size.toFloat(), vertex)
            }
        }
        fence.circles.forEach { circle ->
            val command = if (circle.inclusion) FENCE_CIRCLE_INCLUSION else FENCE_CIRCLE_EXCLUSION
            items += fenceItem(items.size, command, circle.radiusMetres.toFloat(), circle.center)
        }
        return items
    }

    /** The RALLY list of [points], seq from 0. */
    public fun rallyItems(points: List<PlanPosition>): List<MissionItem> = points.mapIndexed { seq, point ->
        MissionItem(
            seq = seq, frame = MavFrames.GLOBAL_RELATIVE_ALT, command = RALLY_POINT,
            x = wire(point.latitude), y = wire(point.longitude), z = point.altitude.toFloat(), missionType = MissionType.RALLY,
        )
    }

    /**
     * The fence that the FENCE list [items] describes.
     *
     * @throws PlanListException when an item is no fence command, or a polygon's vertices do not add up to the
     *   count its items announce.
     */
    public fun fence(items: List<MissionItem>): PlanGeoFence {
        val polygons = mutableListOf<FencePolygon>()
        val circles = mutableListOf<FenceCircle>()
        var index = 0
        while (index < items.size) {
            val item = items[index]
            when (item.command) {
                FENCE_POLYGON_INCLUSION, FENCE_POLYGON_EXCLUSION -> {
                    val count = item.param1.takeIf { it >= 3 && it == it.roundToInt().toFloat() }?.roundToInt()
                        ?: throw PlanListException(index, "a polygon vertex announces ${item.param1} vertices, at least 3 are needed")
                    if (index + count > items.size) throw PlanListException(index, "a polygon of $count vertices runs past the list's end")
                    val vertices = items.subList(index, index + count)
                    vertices.forEachIndexed { offset, vertex ->
                        if (vertex.command != item.command || vertex.param1 != item.param1) {
                            throw PlanListException(index + offset, "vertex ${offset + 1} of a $count-vertex polygon is command ${vertex.command}")
                        }
                    }
                    polygons += FencePolygon(item.command == FENCE_POLYGON_INCLUSION, vertices.map { PlanPoint(it.latitude, it.longitude) })
                    index += count
                }
                FENCE_CIRCLE_INCLUSION, FENCE_CIRCLE_EXCLUSION -> {
                    circles += FenceCircle(item.command == FENCE_CIRCLE_INCLUSION, PlanPoint(item.latitude, item.longitude), item.param1.toDouble())
                    index++
                }
                else -> throw PlanListException(index, "command ${item.command} is not a fence polygon vertex or circle")
            }
        }
        return PlanGeoFence(polygons, circles)
    }

    /**
     * The rally points that the RALLY list [items] describes.
     *
     * @throws PlanListException when an item is not MAV_CMD_NAV_RALLY_POINT.
     */
    public fun rallyPoints(items: List<MissionItem>): List<PlanPosition> = items.mapIndexed { index, item ->
        if (item.command != RALLY_POINT) throw PlanListException(index, "command ${item.command} is not a rally point ($RALLY_POINT)")
        PlanPosition(item.latitude, item.longitude, item.z.toDouble())
    }

    private fun fenceItem(seq: Int, command: Int, param1: Float, point: PlanPoint) = MissionItem(
        seq = seq, frame = MavFrames.GLOBAL, command = command, param1 = param1,
        x = wire(point.latitude), y = wire(point.longitude), missionType = MissionType.FENCE,
    )

    private fun wire(degrees: Double): Int = Math.round(degrees * 1e7).toInt()
}

/** A fence or rally list from a vehicle that does not describe a fence or rally points; [seq] names the item. */
public class PlanListException(
    /** The seq of the offending item. */
    public val seq: Int,
    /** What is wrong with it. */
    public val reason: String,
) : pod.core.PodException("item $seq: $reason")
