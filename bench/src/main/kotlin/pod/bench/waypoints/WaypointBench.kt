package pod.bench.waypoints

import kotlinx.coroutines.Dispatchers
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
        fun parse(args: Array<String>): WaypointBenchOptions {
            var o = WaypointBenchOptions()
            var i = 0
            while (i < args.size) {
                val value = args.getOrNull(i + 1) ?: error("missing value after ${args[i]}")
                fun number(range: ClosedFloatingPointRange<Double>) = value.toDouble().also { require(it in range) { "${args[i]} must be in $range, was $it" } }
                o = when (args[i]) {
                    "--autopilots" -> o.copy(autopilots = value.split(',').map { Autopilot.valueOf(it.trim().uppercase()) })
                    "--conditions" -> o.copy(conditions = value.split(',').map { LinkCondition.valueOf(it.trim().uppercase().replace('-', '_')) })
                    "--mechanisms" -> o.copy(mechanisms = value.split(',').map { Mechanism.valueOf(it.trim().uppercase().replace('-', '_')) })
                    "--waypoints" -> o.copy(waypoints = number(2.0..50.0).toInt())
                    "--spacing" -> o.copy(spacing = number(5.0..500.0))
                    "--height" -> o.copy(height = number(5.0..120.0))
                    "--action" -> o.copy(action = Duration.parse(value).also { require(it in 0.seconds..60.seconds) { "action must be in 0..60s, was $it" } })
                    "--reps" -> o.copy(reps = number(1.0..20.0).toInt())
                    "--limit" -> o.copy(limit = Duration.parse(value).also { require(it in 1.minutes..30.minutes) { "limit must be in 1m..30m, was $it" } })
                    "--seed" -> o.copy(seed = value.toLong())
                    "--json" -> o.copy(json = File(value))
                    "--markdown" -> o.copy(markdown = File(value))
                    else -> error("unknown option ${args[i]}")
                }
                i += 2
            }
            return o
        }
    }
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

