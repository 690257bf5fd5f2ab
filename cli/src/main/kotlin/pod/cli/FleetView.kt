package pod.cli

import pod.core.vehicle.ConnectionState
import pod.mavlink.FleetEvent
import pod.mavlink.MavlinkVehicle
import java.util.Locale

/** Renders a fleet for people (a table) and for scripts (JSON lines). */
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

    fun eventJson(event: FleetEvent): String {
        val id = event.vehicle.identity.value
        val name = when (event) {
            is FleetEvent.Found -> "found"
            is FleetEvent.Lost -> "lost"
            is FleetEvent.Regained -> "regained"
        }
        return jsonLine(
            "event" to name, "sysid" to id.systemId, "compid" to id.componentId,
            "type" to id.type.name, "autopilot" to id.autopilot.name,
            "silence_ms" to (event as? FleetEvent.Lost)?.silence?.inWholeMilliseconds,
        )
    }

    fun telemetryJson(v: MavlinkVehicle): String {
        val t = v.telemetry
        val pos = t.position.value
        val battery = t.battery.value
        val gps = t.gps.value
        return jsonLine(
            "event" to "telemetry", "sysid" to v.systemId,
            "connected" to (v.connection.value == ConnectionState.CONNECTED),
            "lat" to pos?.location?.latitude, "lon" to pos?.location?.longitude,
            "alt_msl" to pos?.location?.altitude?.meters, "alt_rel" to pos?.relativeAltitude?.meters,
            "heading" to pos?.heading?.degrees,
            "battery" to battery?.remaining, "voltage" to battery?.voltage,
            "mode" to t.mode.value?.name, "armed" to t.armed.value, "landed" to t.landedState.value.name,
            "gps_fix" to gps?.fix?.name, "satellites" to gps?.satellites,
            "link" to t.linkQuality.value.fraction, "lost_frames" to t.linkQuality.value.lost,
        )
    }
}
