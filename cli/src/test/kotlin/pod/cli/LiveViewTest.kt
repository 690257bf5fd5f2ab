package pod.cli

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainInOrder
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import pod.mavlink.radio.RadioStatus

class LiveViewTest : StringSpec({

    "away from a terminal the live view prints the table as plain lines and each event as a line" {
        val out = RecordedLines()
        val view = LiveView(out, json = false)
        view.note("listening on /127.0.0.1:14550 (local port 14550)")
        view.draw(FLEET.filter { it.connected })
        view.note("LOST vehicle 3: silent for 3.0 s")
        view.draw(FLEET)
        out.lines.joinToString("\n") shouldNotContain ESC
        out.lines.first() shouldBe "listening on /127.0.0.1:14550 (local port 14550)"
        out.lines.filter { "SYSID" in it }.size shouldBe 2
        out.lines.map { it.trim().substringBefore(' ') } shouldContainInOrder listOf("SYSID", "1", "2", "", "LOST", "SYSID", "1", "2", "3", "")
    }

    "a radio's report shows under the table as one line, local/remote, and only once a radio has reported" {
        val out = RecordedLines()
        val view = LiveView(out, json = false)
        view.draw(FLEET)
        out.lines.none { it.startsWith("radio") } shouldBe true
        view.draw(FLEET, RadioStatus(51, 68, rssi = 180, remrssi = 175, txbuf = 97, noise = 40, remnoise = 38, rxerrors = 3, fixed = 1))
        out.lines.filter { it.startsWith("radio") } shouldBe listOf("radio 51/68: rssi 180/175 noise 40/38 txbuf 97% rxerrors 3 fixed 1")
    }

    "a radio whose signal is within 10 of its noise is shown red, as MAVProxy shows it" {
        FleetView.radioStyle(RadioStatus(51, 68, rssi = 45, remrssi = 175, txbuf = 97, noise = 40, remnoise = 38, rxerrors = 0, fixed = 0)) shouldBe com.github.ajalt.mordant.rendering.TextColors.red
        FleetView.radioStyle(RadioStatus(51, 68, rssi = 180, remrssi = 175, txbuf = 97, noise = 40, remnoise = 38, rxerrors = 0, fixed = 0)) shouldBe com.github.ajalt.mordant.rendering.TextColors.green
    }

    "with --json the view says nothing for people" {
        val out = RecordedLines()
        val view = LiveView(out, json = true)
        view.note("listening")
        out.lines shouldBe emptyList()
    }

    "a terminal that is not interactive gets plain lines too, without escapes" {
        val (terminal, recorder) = recordingTerminal(interactive = false)
        val view = LiveView(TerminalOutput(terminal), json = false)
        view.draw(FLEET)
        view.note("regained vehicle 3")
        recorder.output() shouldNotContain ESC
        recorder.output().lines().filter { it.isNotBlank() }.last() shouldBe "regained vehicle 3"
    }

    "at a terminal the table is redrawn in place by cursor moves, in colour, with the latest events under it" {
        val (terminal, recorder) = recordingTerminal(interactive = true)
        val view = LiveView(TerminalOutput(terminal), json = false)
        view.draw(FLEET.filter { it.connected })
        recorder.clearOutput()
        for (i in 1..10) view.note("event $i")
        view.draw(FLEET)
        val redrawn = recorder.output()
        redrawn shouldContain Regex("$ESC\\[\\d+A") // the cursor goes back up over the previous frame
        redrawn shouldNotContain "$ESC[2J" // rather than clearing the whole screen
        val lastFrame = redrawn.substringAfterLast("SYSID")
        lastFrame shouldContain "LOST"
        lastFrame shouldContain RED
        // The eight latest events, oldest first, under the table.
        lastFrame.lines().filter { it.startsWith("event ") } shouldBe (3..10).map { "event $it" }
        lastFrame.indexOf("event 3") shouldBeGreaterThan lastFrame.indexOf("LOST")
    }

    "while the table is live a printed line goes above it; once stopped, below it" {
        val (terminal, recorder) = recordingTerminal(interactive = true)
        val view = LiveView(TerminalOutput(terminal), json = false)
        view.draw(FLEET)
        terminal.println("a line printed while the table is live")
        recorder.output().trimEnd().lines().last() shouldNotContain "a line printed"
        view.stop()
        recorder.clearOutput()
        terminal.println("demo done")
        recorder.output() shouldBe "demo done\n"
    }
})
