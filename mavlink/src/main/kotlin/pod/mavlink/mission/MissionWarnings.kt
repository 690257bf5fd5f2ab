package pod.mavlink.mission

import pod.core.units.Location
import pod.mavlink.MavFrames
import java.util.Locale

/**
 * What looks wrong in a mission that a vehicle would still accept: a waypoint below home, or far
 * from home or from the item before it (a digit dropped from a coordinate, an altitude typed
 * negative). Said before an upload, never refused: a long survey may mean it.
 */
public object MissionWarnings {
    /** Farther than this from home or from the previous item, an item is worth a word. */
    public const val FAR_METRES: Double = 5_000.0

    /**
     * One line per suspicious item of [items] (numbered by seq), measured from [home] (AMSL; null:
     * unknown, so only the distances between items are checked).
     */
    public fun of(items: List<MissionItem>, home: Location?): List<String> {
        val warnings = ArrayList<String>()
        var previous: Pair<MissionItem, Location>? = null
        for (item in items) {
            if (!item.isGlobal || item.command !in POSITIONED || (item.x == 0 && item.y == 0)) continue
            val at = Location(item.latitude, item.longitude)
            val relative = item.frame == MavFrames.GLOBAL_RELATIVE_ALT || item.frame == MavFrames.GLOBAL_RELATIVE_ALT_INT
            val belowHome = when {
                relative -> -item.z.toDouble()
                home != null && (item.frame == MavFrames.GLOBAL || item.frame == MavFrames.GLOBAL_INT) -> home.altitude.meters - item.z
                else -> 0.0
            }
            if (belowHome > 0) warnings += "item ${item.seq} is ${belowHome.let(::metres)} below home"
            if (home != null) {
                val fromHome = Location(home.latitude, home.longitude).distanceTo(at).meters
                if (fromHome > FAR_METRES) warnings += "item ${item.seq} is ${fromHome.let(::metres)} from home"
            }
            previous?.let { (before, where) ->
                val step = where.distanceTo(at).meters
                if (step > FAR_METRES) warnings += "item ${item.seq} is ${step.let(::metres)} from item ${before.seq} before it"
            }
            previous = item to at
        }
        return warnings
    }

    private fun metres(value: Double): String = if (value >= 1000) String.format(Locale.ROOT, "%.1f km", value / 1000) else String.format(Locale.ROOT, "%.0f m", value)

    /** Commands that fly to their position (waypoints, loiters, land, takeoff, spline, VTOL). */
    private val POSITIONED = setOf(16, 17, 18, 19, 21, 22, 31, 82, 84, 85)
}
