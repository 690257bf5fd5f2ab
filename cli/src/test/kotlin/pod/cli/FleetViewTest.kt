package pod.cli

import com.github.ajalt.mordant.rendering.AnsiLevel
import com.github.ajalt.mordant.terminal.Terminal
import com.github.ajalt.mordant.terminal.TerminalRecorder
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain

/** A copter flying, a plane on the ground with a low battery and a poor link, and a lost copter. */
internal val FLEET = listOf(
    VehicleRow(3, "quadrotor", "px4", connected = false, 41.1790000, -8.5950000, 101.0, 0.6, "AUTO.MISSION", armed = true, link = 1.0),
    VehicleRow(1, "quadrotor", "ardupilot", connected = true, 41.1785123, -8.5957456, 120.04, 0.98, "GUIDED", armed = true, link = 1.0),
    VehicleRow(2, "fixed_wing", "ardupilot", connected = true, 41.17, -8.59, 80.0, 0.12, "MANUAL", armed = false, link = 0.5),
)

internal const val ESC = "\u001b"
/** Red or green text, whatever other attributes (bold) come with it. */
internal val RED = Regex("$ESC\\[31[;m]")
internal val GREEN = Regex("$ESC\\[32[;m]")

/** A terminal that records what is drawn on it, interactive (colours, cursor moves) or not. */
internal fun recordingTerminal(interactive: Boolean): Pair<Terminal, TerminalRecorder> {
    val recorder = TerminalRecorder(
        ansiLevel = if (interactive) AnsiLevel.ANSI16 else AnsiLevel.NONE, width = 200, height = 60,
        outputInteractive = interactive, inputInteractive = interactive,
    )
    return Terminal(terminalInterface = recorder) to recorder
}

class FleetViewTest : StringSpec({

    "the plain fleet table has a header and one row per vehicle by system id, columns lined up, no escapes" {
        val lines = FleetView.plainLines(FleetView.table(FLEET)).filter { it.isNotBlank() }
        lines shouldHaveSize 4
        lines.joinToString("\n") shouldNotContain ESC
        val header = lines[0]
        for (column in listOf("SYSID", "TYPE", "AUTOPILOT", "STATE", "LAT", "LON", "ALT MSL", "BATT", "MODE", "ARMED", "LINK")) header shouldContain column
        lines.drop(1).map { it.trim().substringBefore(' ') } shouldBe listOf("1", "2", "3")
        val copter = lines[1]
        for (value in listOf("quadrotor", "ardupilot", "connected", "41.1785123", "-8.5957456", "120.0 m", "98%", "GUIDED", "yes", "100%")) copter shouldContain value
        lines[3] shouldContain "LOST"
        // Left-aligned columns start where their header starts; right-aligned ones end where it ends.
        lines.drop(1).zip(listOf("GUIDED", "MANUAL", "AUTO.MISSION")).forEach { (row, mode) -> row.indexOf(mode) shouldBe header.indexOf("MODE") }
        copter.indexOf("98%") + "98%".length shouldBe header.indexOf("BATT") + "BATT".length
        lines[2].indexOf("12%") + "12%".length shouldBe header.indexOf("BATT") + "BATT".length
    }

    "a vehicle with no position or battery yet shows dashes" {
        val lines = FleetView.plainLines(FleetView.table(listOf(VehicleRow(7, "quadrotor", "ardupilot", connected = true))))
        lines[1].split(Regex(" +")).filter { it.isNotEmpty() } shouldBe
            listOf("7", "quadrotor", "ardupilot", "connected", "-", "-", "-", "-", "-", "no", "100%")
    }

    "at a colour terminal a LOST row is red, a connected one green, and a low battery and a poor link red" {
        val (terminal, _) = recordingTerminal(interactive = true)
        val lines = terminal.render(FleetView.table(FLEET)).lines()
        val lost = lines.single { "LOST" in it }
        lost shouldContain RED
        lost shouldNotContain GREEN // not even its state
        val copter = lines.single { "GUIDED" in it }
        copter shouldContain GREEN
        copter shouldNotContain RED
        val plane = lines.single { "MANUAL" in it }
        plane.substringAfter("MANUAL") shouldContain RED // the link, 50 %
        plane.substringBefore("MANUAL").substringAfter("-8.5900000") shouldContain RED // the battery, 12 %
    }
})
