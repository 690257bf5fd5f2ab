package pod.cli

import com.github.ajalt.mordant.rendering.AnsiLevel
import com.github.ajalt.mordant.rendering.BorderType
import com.github.ajalt.mordant.rendering.TextAlign
import com.github.ajalt.mordant.rendering.TextColors
import com.github.ajalt.mordant.rendering.TextStyle
import com.github.ajalt.mordant.rendering.TextStyles
import com.github.ajalt.mordant.rendering.Widget
import com.github.ajalt.mordant.table.Borders
import com.github.ajalt.mordant.table.table
import com.github.ajalt.mordant.terminal.Terminal
import pod.core.units.toReadable
import pod.core.vehicle.ConnectionState
import pod.mavlink.FleetEvent
import pod.mavlink.MavlinkVehicle
import pod.mavlink.radio.RadioStatus
import java.util.Locale

/** One vehicle as the fleet table shows it: a snapshot of its identity and telemetry. */
internal data class VehicleRow(
    val sysid: Int,
    val type: String,
    val autopilot: String,
    val connected: Boolean,
    val latitude: Double? = null,
    val longitude: Double? = null,
    val altitudeMsl: Double? = null,
    /** Remaining charge, 0..1, or null when the vehicle does not estimate it. */
    val battery: Double? = null,
    val mode: String? = null,
    val armed: Boolean = false,
    /** Fraction of the vehicle's frames that arrived, 0..1. */
    val link: Double = 1.0,
)

/** Renders a fleet for people (a Mordant table); pod.cli.json has the JSON lines for scripts. */
internal object FleetView {

    /** Below this charge the battery cell is red: the demo's Listing 4 replaces a drone there. */
    private const val LOW_BATTERY = 0.3
    private const val FAIR_BATTERY = 0.5

    /** Below this share of frames arriving the link cell is red; below [FAIR_LINK], yellow. */
    private const val POOR_LINK = 0.8
    private const val FAIR_LINK = 0.95

    private val HEADER = listOf("SYSID", "TYPE", "AUTOPILOT", "STATE", "LAT", "LON", "ALT MSL", "BATT", "MODE", "ARMED", "LINK")

    /** The numeric columns, right-aligned so that their digits line up. */
    private val RIGHT_ALIGNED = listOf(0, 4, 5, 6, 7, 10)

    fun row(v: MavlinkVehicle): VehicleRow {
        val id = v.identity.value
        val t = v.telemetry
        val pos = t.position.value
        return VehicleRow(
            sysid = id.systemId,
            type = id.type.name.lowercase(),
            autopilot = id.autopilot.name.lowercase(),
            connected = v.connection.value == ConnectionState.CONNECTED,
            latitude = pos?.location?.latitude,
            longitude = pos?.location?.longitude,
            altitudeMsl = pos?.location?.altitude?.meters,
            battery = t.battery.value?.remaining,
            mode = t.mode.value?.name,
            armed = t.armed.value,
            link = t.linkQuality.value.fraction,
        )
    }

    /**
     * The fleet as a table, one row per vehicle by system id. Its colours (a LOST row red, armed
     * yellow, low battery and a poor link red) show only on a terminal that takes them: rendered
     * by [plainLines] it is plain text.
     */
    fun table(rows: Collection<VehicleRow>): Widget = table {
        // Columns apart by spaces, no box: the same layout reads well at a terminal, in a log and to grep.
        borderType = BorderType.BLANK
        tableBorders = Borders.NONE
        cellBorders = Borders.LEFT_RIGHT
        padding { horizontal = 0 }
        RIGHT_ALIGNED.forEach { column(it) { align = TextAlign.RIGHT } }
        header {
            style = TextStyles.bold.style
            rowFrom(HEADER)
        }
        body {
            rows.sortedBy { it.sysid }.forEach { r ->
                val cells = listOf(
                    r.sysid.toString(), r.type, r.autopilot, if (r.connected) "connected" else "LOST",
                    r.latitude?.let { "%.7f".format(Locale.ROOT, it) } ?: "-",
                    r.longitude?.let { "%.7f".format(Locale.ROOT, it) } ?: "-",
                    r.altitudeMsl?.let { "%.1f m".format(Locale.ROOT, it) } ?: "-",
                    r.battery?.let { percent(it) } ?: "-",
                    r.mode ?: "-",
                    if (r.armed) "yes" else "no",
                    percent(r.link),
                )
                if (!r.connected) {
                    // A lost vehicle's last values are stale: the whole row says so.
                    row {
                        style = TextColors.red + TextStyles.bold
                        cellsFrom(cells)
                    }
                } else {
                    row {
                        cells.forEachIndexed { i, text ->
                            cell(text) {
                                style = when (i) {
                                    3 -> TextColors.green
                                    7 -> r.battery?.let { level(it, LOW_BATTERY, FAIR_BATTERY) }
                                    9 -> if (r.armed) TextColors.yellow + TextStyles.bold else null
                                    10 -> level(r.link, POOR_LINK, FAIR_LINK)
                                    else -> null
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    /** The [table] (or any widget) as plain lines: no colour, no escapes, trailing spaces trimmed. */
    fun plainLines(widget: Widget): List<String> = PLAIN.render(widget).lines().map { it.trimEnd() }

    /** Renders without colour and wide enough that no table wraps, whatever the real terminal is. */
    private val PLAIN = Terminal(ansiLevel = AnsiLevel.NONE, width = 400, height = 400, hyperlinks = false, interactive = false)

    private fun percent(fraction: Double): String = "%.0f%%".format(Locale.ROOT, fraction * 100)

    private fun level(value: Double, poor: Double, fair: Double): TextStyle = when {
        value < poor -> TextColors.red
        value < fair -> TextColors.yellow
        else -> TextColors.green
    }

    /**
     * The link's radio for people, under the table: `radio 51/68: rssi 180/175 noise 40/38 txbuf 98%
     * rxerrors 0 fixed 0` (local/remote). MAVProxy's console marks a radio red when a signal is
     * within 10 of its noise (mavproxy_console.py, handle_radio_status); so does the live view.
     */
    fun radioLine(r: RadioStatus): String =
        "radio ${r.systemId}/${r.componentId}: rssi ${r.rssi}/${r.remrssi} noise ${r.noise}/${r.remnoise} txbuf ${r.txbuf}% rxerrors ${r.rxerrors} fixed ${r.fixed}"

    /** Red when either radio hears its signal within 10 of its noise, as MAVProxy shows it. */
    fun radioStyle(r: RadioStatus): TextStyle = if (r.rssi < r.noise + 10 || r.remrssi < r.remnoise + 10) TextColors.red else TextColors.green

    fun eventLine(event: FleetEvent): String {
        val id = event.vehicle.identity.value
        return when (event) {
            is FleetEvent.Found -> "found vehicle ${id.systemId}: ${id.type.name.lowercase()} on ${id.autopilot.name.lowercase()}"
            is FleetEvent.Lost -> "LOST vehicle ${id.systemId}: silent for ${event.silence.toReadable()}"
            is FleetEvent.Regained -> "regained vehicle ${id.systemId}"
        }
    }

    /** How an event line stands out under the live table: a lost vehicle red, a regained one green. */
    fun eventStyle(event: FleetEvent): TextStyle? = when (event) {
        is FleetEvent.Found -> null
        is FleetEvent.Lost -> TextColors.red + TextStyles.bold
        is FleetEvent.Regained -> TextColors.green
    }

}
