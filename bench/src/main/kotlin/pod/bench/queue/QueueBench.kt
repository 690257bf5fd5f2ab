package pod.bench.queue

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.runBlocking
import pod.core.vehicle.Autopilot
import kotlin.time.TimeSource

/**
 * Issue 14's benchmark: how long a change of the element being flown takes to reach the vehicle —
 * `replaceCurrent` on the vehicle's mission queue (one DO_REPOSITION in GUIDED) against
 * re-uploading the whole equivalent mission in AUTO and MISSION_SET_CURRENT — timed from the
 * ground's call to the moment the simulated ArduCopter steers for the new point (its
 * [pod.sim.SimState.target], stamped on the simulator's thread).
 *
 * Real UDP sockets on 127.0.0.1, the simulator in real time (time scale 1), one fresh station and
 * vehicle per link condition: straight on loopback, or through a [pod.sim.fault.LossyRelay] with a
 * 50 ms delay each way (100 ms round trip) and optionally 20 % loss each way. Per condition and
 * queue length N: the queue case, then the re-upload case, each [QueueBenchOptions.warmUp]
 * changes not kept and [QueueBenchOptions.reps] kept.
 *
 * Usage: `QueueBenchKt [--sizes 10,100] [--conditions LOOPBACK,RTT100,RTT100_LOSS20]
 * [--methods QUEUE,REUPLOAD] [--reps 30] [--warmup 5] [--lossy-reps 10] [--gap 300ms]
 * [--limit 60s] [--seed 1] [--json FILE] [--markdown FILE]`. Every wait is bounded (set-up steps
 * by their own timeouts, each change by the limit), so the program ends by itself.
 */
fun main(args: Array<String>) {
    val o = QueueBenchOptions.parse(args)
    val started = TimeSource.Monotonic.markNow()
    val changes = runBlocking(Dispatchers.Default) {
        o.conditions.flatMapIndexed { i, condition ->
            coroutineScope {
                println("== ${condition.label}: taking off")
                val rig = QueueRig.airborne(this, Autopilot.ARDUPILOT, condition, o.seed * 100 + i)
                try {
                    val reps = o.repsFor(condition)
                    o.sizes.flatMap { n ->
                        o.methods.flatMap { method ->
                            val runs = when (method) {
                                ChangeMethod.QUEUE -> rig.queueChanges(n, condition, o.warmUp, reps, o.gap, o.limit)
                                ChangeMethod.REUPLOAD -> rig.reuploadChanges(n, condition, o.warmUp, reps, o.gap, o.limit)
                            }
                            println("  " + QueueReport.line(runs))
                            runs.filter { it.error != null }.groupBy { it.error }.forEach { (error, failed) ->
                                val ground = failed.mapNotNull { it.groundMs }
                                val returned = if (ground.isEmpty()) "" else "; the ground's calls had returned in ${ground.size} of them, after " + ground.joinToString { "%.0f ms".format(java.util.Locale.ROOT, it) }
                                println("    ${failed.size} failed: $error$returned")
                            }
                            runs
                        }
                    }
                } finally {
                    rig.close()
                    coroutineContext.cancelChildren()
                }
            }
        }
    }
    val wall = started.elapsedNow()
    println("== done in $wall")
    val markdown = QueueReport.markdown(changes, o)
    println()
    println(markdown)
    o.json?.let { it.parentFile?.mkdirs(); it.writeText(QueueReport.json(changes, o, wall)); println("wrote ${it.path}") }
    o.markdown?.let { it.parentFile?.mkdirs(); it.writeText(markdown); println("wrote ${it.path}") }
}
