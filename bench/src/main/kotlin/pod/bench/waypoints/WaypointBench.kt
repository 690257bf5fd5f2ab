package pod.bench.waypoints

import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.long
import kotlinx.coroutines.Dispatchers
import pod.bench.BenchCommand
import pod.bench.ReportFiles
import pod.bench.count
import pod.bench.duration
import pod.bench.names
import pod.bench.number
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import pod.bench.queue.LinkCondition
import pod.bench.queue.QueueRig
import pod.core.units.m
import pod.core.vehicle.Autopilot
import java.io.File
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/** One flight's result: which autopilot, link and mechanism, and its figures (or why it failed). */
data class Flight(val autopilot: Autopilot, val condition: LinkCondition, val mechanism: Mechanism, val rep: Int, val timings: FlightTimings?, val error: String? = null)

/** Command line of the waypoint benchmark; see [main]. */
data class WaypointBenchOptions(
    val autopilots: List<Autopilot> = listOf(Autopilot.ARDUPILOT, Autopilot.PX4),
    val conditions: List<LinkCondition> = listOf(LinkCondition.LOOPBACK, LinkCondition.RTT100),
    val mechanisms: List<Mechanism> = Mechanism.entries,
    val waypoints: Int = 8,
    val spacing: Double = 40.0,
    val height: Double = 30.0,
    val action: Duration = 2.seconds,
    val reps: Int = 1,
    val limit: Duration = 10.minutes,
    val seed: Long = 1,
    val json: File? = null,
    val markdown: File? = null,
) {
    companion object {
        /** The options [args] give (see [main] for the list). */
        fun parse(args: Array<String>): WaypointBenchOptions = WaypointBenchCommand().parse(args)
    }
}

/** [WaypointBenchOptions] read from the command line. */
private class WaypointBenchCommand : BenchCommand<WaypointBenchOptions>("WaypointBenchKt", "What stopping at a waypoint for an action costs, per mechanism.") {
    private val d = WaypointBenchOptions()
    private val autopilots by option("--autopilots").names<Autopilot>().default(d.autopilots)
    private val conditions by option("--conditions").names<LinkCondition>().default(d.conditions)
    private val mechanisms by option("--mechanisms").names<Mechanism>().default(d.mechanisms)
    private val waypoints by option("--waypoints").count(2..50).default(d.waypoints)
    private val spacing by option("--spacing", help = "metres between waypoints").number(5.0..500.0).default(d.spacing)
    private val height by option("--height", help = "metres above home").number(5.0..120.0).default(d.height)
    private val action by option("--action", help = "how long each action takes").duration(0.seconds..60.seconds).default(d.action)
    private val reps by option("--reps").count(1..20).default(d.reps)
    private val limit by option("--limit", help = "longest flight").duration(1.minutes..30.minutes).default(d.limit)
    private val seed by option("--seed").long().default(d.seed)
    private val report by ReportFiles()

    override fun options(): WaypointBenchOptions =
        WaypointBenchOptions(autopilots, conditions, mechanisms, waypoints, spacing, height, action, reps, limit, seed, report.json, report.markdown)
}

/**
 * Issue 15's benchmark: what stopping at a waypoint to run an action costs, per mechanism and
 * autopilot, in the vehicle's own time. A simulated ArduCopter or PX4 copter (real time, time
 * scale 1) flies [WaypointBenchOptions.waypoints] waypoints in a straight line, an action of
 * [WaypointBenchOptions.action] at each, through real UDP sockets on 127.0.0.1, straight or through
 * a relay with 50 ms delay each way; each mechanism of [Mechanism] in turn, the line flown
 * alternately north and south. Every figure comes from the simulator's published states and its
 * clock ([Trace], [TimingAnalysis]).
 *
 * Usage: `WaypointBenchKt [--autopilots ARDUPILOT,PX4] [--conditions LOOPBACK,RTT100]
 * [--mechanisms NONSTOP,QUEUE,MODE_SWITCH,HOLD_SET_CURRENT] [--waypoints 8] [--spacing 40]
 * [--height 30] [--action 2s] [--reps 1] [--limit 10m] [--seed 1] [--json FILE] [--markdown FILE]`.
 * Every flight is bounded by the limit and every set-up step by its own timeout.
 */
fun main(args: Array<String>) {
    val o = WaypointBenchOptions.parse(args)
    val started = TimeSource.Monotonic.markNow()
    val flights = runBlocking(Dispatchers.Default) {
        var run = 0
        o.autopilots.flatMap { autopilot ->
            o.conditions.flatMap { condition ->
                coroutineScope {
                    println("== $autopilot, ${condition.label}: taking off")
                    val rig = QueueRig.airborne(this, autopilot, condition, o.seed * 100 + run, o.height.m)
                    val trace = Trace.record(this, rig.sim)
                    try {
                        (1..o.reps).flatMap { rep ->
                            o.mechanisms.map { mechanism ->
                                holdStill(rig)
                                trace.clear()
                                val course = WaypointCourse(rig, trace, autopilot, o.waypoints, o.spacing, o.height, o.action, north = run++ % 2 == 0)
                                val from = trace.now()
                                val flight = try {
                                    val actions = course.fly(mechanism, o.limit)
                                    Flight(autopilot, condition, mechanism, rep, TimingAnalysis.analyse(trace.states(), from, course.waypoints, actions))
                                } catch (e: kotlinx.coroutines.TimeoutCancellationException) {
                                    Flight(autopilot, condition, mechanism, rep, null, "not done within ${o.limit}")
                                } catch (e: kotlinx.coroutines.CancellationException) {
                                    throw e
                                } catch (e: Exception) {
                                    Flight(autopilot, condition, mechanism, rep, null, "${e::class.simpleName}: ${e.message}")
                                }
                                println("  " + WaypointReport.line(flight, o))
                                flight
                            }
                        }
                    } finally {
                        trace.stop()
                        rig.close()
                        coroutineContext.cancelChildren()
                    }
                }
            }
        }
    }
    val wall = started.elapsedNow()
    println("== done in $wall")
    val markdown = WaypointReport.markdown(flights, o)
    println()
    println(markdown)
    o.json?.let { it.parentFile?.mkdirs(); it.writeText(WaypointReport.json(flights, o, wall)); println("wrote ${it.path}") }
    o.markdown?.let { it.parentFile?.mkdirs(); it.writeText(markdown); println("wrote ${it.path}") }
}

/** Puts the vehicle in its hold mode and waits (bounded) until the simulator says it has stopped. */
private suspend fun holdStill(rig: QueueRig) {
    withTimeout(60.seconds) {
        rig.vehicle.action.hold()
        rig.sim.state.first { it.groundSpeed.metersPerSecond < 0.1 && kotlin.math.abs(it.climbRate.metersPerSecond) < 0.1 }
    }
}

