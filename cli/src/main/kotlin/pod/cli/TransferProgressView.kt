package pod.cli

import com.github.ajalt.mordant.animation.progress.MultiProgressBarAnimation
import com.github.ajalt.mordant.animation.progress.ProgressTask
import com.github.ajalt.mordant.animation.progress.addTask
import com.github.ajalt.mordant.rendering.TextAlign
import com.github.ajalt.mordant.widgets.progress.progressBar
import com.github.ajalt.mordant.widgets.progress.progressBarLayout
import com.github.ajalt.mordant.widgets.progress.speed
import com.github.ajalt.mordant.widgets.progress.marquee
import com.github.ajalt.mordant.widgets.progress.text
import com.github.ajalt.mordant.widgets.progress.timeRemaining
import pod.mavlink.mission.TransferProgress
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.TimeSource

/**
 * Shows a mission transfer's progress to people, and nothing until its total is known (a
 * download learns it from the vehicle's MISSION_COUNT; before that the protocol reports 0 of 0).
 *
 * At an interactive terminal ([Output.liveTerminal]): a Mordant progress bar with items done of
 * the total, the rate in items per second and the time left, redrawn on each [update] and [tick].
 * Elsewhere: a plain line when the total becomes known and one as each quarter is passed
 * ("uploading 13/50 items (26%)").
 */
internal class TransferProgressView(
    private val out: Output,
    private val action: String,
    private val timeSource: TimeSource.WithComparableMarks = TimeSource.Monotonic,
) {
    private val terminal = out.liveTerminal
    private var animation: MultiProgressBarAnimation? = null
    private var task: ProgressTask<Unit>? = null
    private var lastQuarter = -1

    /** Whether the view draws in place, so that [tick] is worth calling while the vehicle is quiet. */
    val animated: Boolean get() = terminal != null

    /** Shows [p]; a report without a total (0 of 0) shows nothing. */
    fun update(p: TransferProgress) {
        if (p.total <= 0) return
        if (terminal == null) {
            val quarter = p.done * 4 / p.total
            if (quarter != lastQuarter) {
                lastQuarter = quarter
                out.line("$action ${p.done}/${p.total} items (${p.done * 100 / p.total}%)")
            }
            return
        }
        val bar = animation ?: MultiProgressBarAnimation(terminal, timeSource = timeSource).also { animation = it }
        val existing = task
        val current = existing ?: bar.addTask(layout(p.total), total = p.total.toLong(), completed = p.done.toLong()).also { task = it }
        if (existing != null) {
            if (existing.finished) return
            existing.update {
                completed = p.done.toLong()
                total = p.total.toLong()
            }
        }
        // Mordant redraws each cell at most a few times a second; the last frame must show the
        // last count, not one cached a moment before. A finished bar stops itself on this refresh
        // and stays on screen.
        bar.refresh(refreshAll = current.finished)
    }

    /** Redraws the bar, so that the rate and the time left move on while no item arrives. */
    fun tick() {
        val bar = animation ?: return
        if (task?.finished == false) bar.refresh()
    }

    /** Leaves the bar as it is on screen (a cancelled or failed transfer's too); what is printed next goes under it. */
    fun finish() {
        val bar = animation ?: return
        if (task?.finished == false) {
            bar.refresh(refreshAll = true)
            bar.stop()
        }
    }

    private fun layout(total: Int) = progressBarLayout {
        text(action)
        progressBar()
        // Mordant's completed() abbreviates (1.2K); a mission's items are counted exactly, in a
        // cell of fixed width (a text cell is squeezed by the bar, and the bar would jump as
        // digits are added).
        marquee(width = "$total/$total items".length, fps = textFps, align = TextAlign.RIGHT) { "$completed/$total items" }
        speed(suffix = " items/s")
        // Once done, how long it took instead of an empty estimate.
        timeRemaining(elapsedWhenFinished = true)
    }

    companion object {
        /** How often [tick] is worth calling. */
        val TICK: Duration = 200.milliseconds
    }
}
