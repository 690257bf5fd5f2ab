package pod.mavlink.action

import pod.core.vehicle.FlightMode
import pod.core.vehicle.LandedState
import pod.core.vehicle.Position
import java.util.Locale

/** A position as people read it in a message: its height above home. */
internal fun heightText(position: Position?): String =
    position?.let { "at %.1f m above home".format(Locale.ROOT, it.relativeAltitude.meters) } ?: "no position reported"

/** A state as people read it: a mode by its name, a flag in words, never a data class's toString. */
internal fun stateText(value: Any?): String = when (value) {
    null -> "nothing"
    is Boolean -> if (value) "armed" else "disarmed"
    is FlightMode -> "mode ${value.name}"
    is Position -> heightText(value)
    is Pair<*, *> -> "${stateText(value.first)}, ${stateText(value.second)}"
    is LandedState -> value.name.lowercase().replace('_', ' ')
    else -> value.toString()
}
