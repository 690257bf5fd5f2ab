package pod.cli

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import io.kotest.matchers.string.shouldStartWith
import pod.mavlink.mission.TransferProgress
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TestTimeSource

class TransferProgressViewTest : StringSpec({

    "away from a terminal a transfer prints a line once its total is known and one per quarter, none before" {
        val out = RecordedLines()
        val view = TransferProgressView(out, "downloading")
        // A download reports 0 of 0 until MISSION_COUNT tells it the total.
        repeat(3) { view.update(TransferProgress(0, 0)) }
        out.lines shouldBe emptyList()
        for (done in 0..25) view.update(TransferProgress(done, 25))
        view.update(TransferProgress(25, 25))
        view.finish()
        out.lines shouldBe listOf(
            "downloading 0/25 items (0%)",
            "downloading 7/25 items (28%)",
            "downloading 13/25 items (52%)",
            "downloading 19/25 items (76%)",
            "downloading 25/25 items (100%)",
        )
    }

    "at a terminal nothing is drawn before the total is known, then a bar with items, rate and time left" {
        val (terminal, recorder) = recordingTerminal(interactive = true)
        val clock = TestTimeSource()
        val view = TransferProgressView(TerminalOutput(terminal), "downloading", clock)
        view.animated shouldBe true
        repeat(3) {
            view.update(TransferProgress(0, 0))
            clock += 1.seconds
            view.tick()
        }
        recorder.output() shouldBe ""
        view.update(TransferProgress(0, 25))
        recorder.output() shouldContain "downloading"
        recorder.output() shouldContain "0/25 items"
        recorder.clearOutput()
        clock += 1.seconds
        view.update(TransferProgress(5, 25))
        val frame = recorder.output()
        frame shouldContain "5/25 items"
        frame shouldContain "5.0 items/s"
        frame shouldContain "eta 0:00:04"
        frame shouldContain "━" // Mordant's bar
        frame shouldStartWith "\r" // drawn over the previous frame, on the same line
    }

    "a finished bar stays on screen once, with the line after it below" {
        val (terminal, recorder) = recordingTerminal(interactive = true)
        val clock = TestTimeSource()
        val out = TerminalOutput(terminal)
        val view = TransferProgressView(out, "uploading", clock)
        for (done in 0..4) {
            view.update(TransferProgress(done, 4))
            clock += 1.seconds
        }
        view.tick()
        view.finish()
        out.line("uploaded 4 mission items to vehicle 1")
        val text = recorder.output()
        Regex("4/4 items").findAll(text).count() shouldBe 1 // neither the tick nor finish() drew it again
        text shouldContain "in 0:00:04" // how long it took
        text.trimEnd().lines().last() shouldBe "uploaded 4 mission items to vehicle 1"
    }

    "a fast transfer's last frame shows its last count, not one Mordant cached a moment before" {
        val (terminal, recorder) = recordingTerminal(interactive = true)
        val view = TransferProgressView(TerminalOutput(terminal), "downloading", TestTimeSource())
        for (done in 0..300) view.update(TransferProgress(done, 300)) // all within one frame's time
        view.finish()
        val frames = recorder.output().split("\r")
        frames.last() shouldContain "300/300 items"
        frames.count { "300/300" in it } shouldBe 1
    }

    "a transfer already complete at its first report still shows its bar" {
        val (terminal, recorder) = recordingTerminal(interactive = true)
        val view = TransferProgressView(TerminalOutput(terminal), "uploading", TestTimeSource())
        view.update(TransferProgress(3, 3))
        view.finish()
        recorder.output() shouldContain "3/3 items"
    }

    "a transfer cut short leaves its bar where it stopped" {
        val (terminal, recorder) = recordingTerminal(interactive = true)
        val view = TransferProgressView(TerminalOutput(terminal), "uploading", TestTimeSource())
        view.update(TransferProgress(0, 500))
        view.update(TransferProgress(120, 500))
        view.finish()
        terminal.println("interrupted by SIGINT: vehicle 74 transfer cancelled")
        val text = recorder.output()
        text.substringAfterLast("SIGINT").let { it shouldNotContain "120/500" }
        text.trimEnd().lines().last() shouldContain "interrupted by SIGINT"
        text.trimEnd().lines().dropLast(1).last() shouldContain "120/500 items"
    }
})
