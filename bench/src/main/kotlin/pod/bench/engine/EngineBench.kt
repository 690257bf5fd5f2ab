package pod.bench.engine

import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.options.split
import pod.bench.BenchCommand
import pod.bench.count
import pod.bench.percentile
import pod.bench.yesNo
import pod.core.engine.Engine
import pod.core.engine.Task
import pod.core.engine.VehicleSet
import pod.core.engine.asSet
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.units.Location
import java.lang.management.ManagementFactory
import java.util.Locale
import kotlin.time.TimeSource

/**
 * Engine overhead: task trees of trivial missions on [InstantPlatform], run as programs on one
 * thread (runBlocking's event loop), so the time is the engine's own — task coroutines, events,
 * claim and release of vehicles — not flying and not parallelism.
 *
 * Cases: `concurrent` = Concurrent(n × Bound(Fly, one vehicle each)); `sequence` = Sequence(n ×
 * Bound(Fly, the same vehicle)); `deep` = n nested Sequence/Concurrent/Watch levels around one Fly.
 *
 * Usage: `EngineBenchKt [--leaves 10000] [--depth 1000] [--warmup 10] [--reps 30] [--yield true]
 * [--events true] [--cases concurrent,sequence,deep]`. --events subscribes a collector to
 * Engine.events (otherwise nobody listens and events are dropped at once).
 */
fun main(args: Array<String>) {
    val o = parse(args)
    println("engine overhead: leaves ${o.leaves}, depth ${o.depth}, warm-up ${o.warmup}, reps ${o.reps}, fly ${if (o.yielding) "yields once" else "returns at once"}, events ${if (o.events) "collected" else "not collected"}")
    println(String.format(Locale.ROOT, "%-11s %6s %9s %9s %9s %9s %9s %11s %11s", "case", "tasks", "mean ms", "p50 ms", "p90 ms", "p99 ms", "min ms", "µs/leaf", "KiB/leaf"))
    for (case in o.cases) {
        val platform = InstantPlatform(if (case == "concurrent") o.leaves else 1, o.yielding)
        val (task, leaves) = when (case) {
            "concurrent" -> Task.Concurrent(platform.fleet.map { Task.Bound(Task.Fly(MISSION), it.asSet()) }) to o.leaves
            "sequence" -> Task.Sequence(List(o.leaves) { Task.Bound(Task.Fly(MISSION), platform.fleet[0].asSet()) }) to o.leaves
            "deep" -> deep(o.depth, platform.fleet[0].asSet()) to 1
            else -> error("unknown case $case")
        }
        val times = mutableListOf<Double>()
        val bytes = mutableListOf<Double>()
        repeat(o.warmup + o.reps) { rep ->
            val allocatedBefore = allocated()
            val started = TimeSource.Monotonic.markNow()
            runBlocking {
                val engine = Engine(platform)
                val collector = if (o.events) launch(start = CoroutineStart.UNDISPATCHED) { engine.events.collect { } } else null
                engine.run { execute(task) }
                collector?.cancel()
            }
            val ms = started.elapsedNow().inWholeNanoseconds / 1e6
            if (rep >= o.warmup) {
                times += ms
                bytes += (allocated() - allocatedBefore).toDouble()
            }
        }
        val mean = times.average()
        println(
            String.format(
                Locale.ROOT, "%-11s %6d %9.2f %9.2f %9.2f %9.2f %9.2f %11.2f %11.2f",
                case, if (case == "deep") o.depth else leaves, mean, percentile(times, 50.0), percentile(times, 90.0), percentile(times, 99.0),
                times.min(), mean * 1000 / (if (case == "deep") o.depth else leaves), bytes.average() / 1024 / (if (case == "deep") o.depth else leaves),
            ),
        )
    }
}

private val MISSION = Mission("leaf", Location(41.18, -8.6), listOf(MissionStep.Waypoint(Location(41.18, -8.6, pod.core.units.Distance.ZERO))))

/** [depth] levels, cycling Sequence, Concurrent and Watch, around one Fly on [vehicles]. */
private fun deep(depth: Int, vehicles: VehicleSet): Task {
    var task: Task = Task.Bound(Task.Fly(MISSION), vehicles)
    repeat(depth) { level ->
        task = when (level % 3) {
            0 -> Task.Sequence(listOf(task))
            1 -> Task.Concurrent(listOf(task))
            else -> Task.Watch(task, pod.core.engine.ErrorHandler.Propagate)
        }
    }
    return task
}

/** Bytes allocated by this thread so far (HotSpot's per-thread counter). */
private fun allocated(): Long = (ManagementFactory.getThreadMXBean() as com.sun.management.ThreadMXBean).currentThreadAllocatedBytes

private data class Options(
    val leaves: Int = 10_000,
    val depth: Int = 1_000,
    val warmup: Int = 10,
    val reps: Int = 30,
    val yielding: Boolean = false,
    val events: Boolean = false,
    val cases: List<String> = listOf("concurrent", "sequence", "deep"),
)

private fun parse(args: Array<String>): Options = EngineBenchCommand().parse(args)

/** [Options] read from the command line. */
private class EngineBenchCommand : BenchCommand<Options>("EngineBenchKt", "Engine overhead on a platform whose missions finish at once.") {
    private val d = Options()
    private val leaves by option("--leaves").count(1..1_000_000).default(d.leaves)
    private val depth by option("--depth").count(1..100_000).default(d.depth)
    private val warmup by option("--warmup").count(0..Int.MAX_VALUE).default(d.warmup)
    private val reps by option("--reps").count(1..Int.MAX_VALUE).default(d.reps)
    private val yielding by option("--yield", help = "each flight yields once").yesNo().default(d.yielding)
    private val events by option("--events", help = "collect Engine.events").yesNo().default(d.events)
    private val cases by option("--cases").convert { it.trim() }.split(",").default(d.cases)

    override fun options(): Options = Options(leaves, depth, warmup, reps, yielding, events, cases)
}
