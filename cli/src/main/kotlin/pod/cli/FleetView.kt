package pod.cli

import pod.core.vehicle.ConnectionState
import pod.mavlink.FleetEvent
import pod.mavlink.MavlinkVehicle
import java.util.Locale

/** Renders a fleet for people (a table); pod.cli.json has the JSON lines for scripts. */
internal object FleetView {

    fun table(vehicles: Collection<MavlinkVehicle>): List<String> {
        val header = String.format(
            Locale.ROOT, "%-5s %-11s %-10s %-10s %12s %13s %8s %7s %-12s %-6s %5s",
            "SYSID", "TYPE", "AUTOPILOT", "STATE", "LAT", "LON", "ALT MSL", "BATT", "MODE", "ARMED", "LINK",
        )
        return listOf(header) + vehicles.sortedBy { it.systemId }.map { v ->
            val id = v.identity.value
            val t = v.telemetry
            val pos = t.position.value
            val battery = t.battery.value
            String.format(
                Locale.ROOT, "%-5d %-11s %-10s %-10s %12s %13s %8s %7s %-12s %-6s %4.0f%%",
                id.systemId, id.type.name.lowercase(), id.autopilot.name.lowercase(),
                if (v.connection.value == ConnectionState.CONNECTED) "connected" else "LOST",
                pos?.let { "%.7f".format(Locale.ROOT, it.location.latitude) } ?: "-",
                pos?.let { "%.7f".format(Locale.ROOT, it.location.longitude) } ?: "-",
                pos?.let { "%.1f m".format(Locale.ROOT, it.location.altitude.meters) } ?: "-",
                battery?.remaining?.let { "%.0f%%".format(Locale.ROOT, it * 100) } ?: "-",
                t.mode.value?.name ?: "-",
                if (t.armed.value) "yes" else "no",
                t.linkQuality.value.fraction * 100,
            )
        }
    }

    fun eventLine(event: FleetEvent): String {
        val id = event.vehicle.identity.value
        return when (event) {
            is FleetEvent.Found -> "found vehicle ${id.systemId}: ${id.type.name.lowercase()} on ${id.autopilot.name.lowercase()}"
            is FleetEvent.Lost -> "LOST vehicle ${id.systemId}: silent for ${event.silence.inWholeMilliseconds} ms"
            is FleetEvent.Regained -> "regained vehicle ${id.systemId}"
        }
    }
}
