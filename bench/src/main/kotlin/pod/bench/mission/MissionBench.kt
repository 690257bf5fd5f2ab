package pod.bench.mission

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.runBlocking
import pod.core.vehicle.Autopilot
import java.util.Locale
import kotlin.time.TimeSource

/**
 * Mission transfer on loopback: Pod's GroundStation (in this JVM) against MAVSDK 4.1's MissionRaw
 * (bench/mavsdk_mission.py, a subprocess) as the ground station, each uploading a mission into a
 * fresh simulated vehicle and downloading it back, through a seeded [pod.sim.fault.LossyRelay]
 * that drops datagrams each way.
 *
 * 1. Floor: ping-pong through the same relay with no faults (median, p99).
 * 2. Grid: flavours × sizes × loss, one seeded run per ground station (same seed for both).
 * 3. Success rate: [MissionBenchOptions.successRuns] seeded runs per ground station and flavour.
 *
 * Usage: `MissionBenchKt [--sizes 10,100,1000] [--losses 0,10,30] [--flavours PX4,ARDUPILOT]
 * [--stations POD,MAVSDK] [--success-runs 20] [--success-items 100] [--success-loss 30]
 * [--floor-samples 2000] [--floor-warmup 500] [--transfer-limit 120s] [--seed 1]
 * [--min-timeout 20ms] [--initial-timeout 500ms]
 * [--python .venv/bin/python] [--mavsdk-script bench/mavsdk_mission.py] [--mavsdk-log FILE]
 * [--json FILE] [--markdown FILE]`. Every run is bounded (discovery 30 s, each transfer by the
 * limit; a run that overruns is a failure), so the program ends by itself.
 */
fun main(args: Array<String>) {
    val o = MissionBenchOptions.parse(args)
    val started = TimeSource.Monotonic.markNow()
    val mavsdk = MavsdkSetup(o.python, o.mavsdkScript, o.mavsdkLog)
    if (Station.MAVSDK in o.stations) {
        require(o.python.canExecute()) { "no Python at ${o.python}: run tools/python-peers.sh" }
        require(o.mavsdkScript.isFile) { "no MAVSDK script at ${o.mavsdkScript}" }
    }
    o.mavsdkLog?.parentFile?.mkdirs()
    val results = runBlocking(Dispatchers.Default) {
        println("== floor: ${o.floorSamples} round trips after ${o.floorWarmUp} warm-up")
        val floor = measureFloor(o.floorWarmUp, o.floorSamples)
        floor.forEach { println(String.format(Locale.ROOT, "  %-32s median %.3f ms  p99 %.3f ms  (%d lost)", it.path, it.medianMs, it.p99Ms, it.lost)) }

        suspend fun run(station: Station, cell: Cell, seed: Long): TransferRun {
            val items = benchMission(cell.items)
            val result = when (station) {
                Station.POD -> podTransfer(cell, seed, items, o.limits, o.timing)
                Station.MAVSDK -> mavsdkTransfer(mavsdk, cell, seed, items, o.limits)
            }
            println("  " + result.describe())
            return result
        }

        if (Station.POD in o.stations) {
            // The first transfers run interpreted and compile as they go: keep them out of the figures.
            // Each flavour at the largest size, so that what the grid times first is compiled like
            // what it times last (100-item PX4 warm-ups left the first 1000-item runs of issue 13
            // still compiling, and PX4's cells come first).
            println("== warm-up (discarded)")
            val size = o.sizes.maxOrNull() ?: 100
            for (flavour in o.flavours) repeat(3) { run(Station.POD, Cell(flavour, size, 0), 0) }
        }

        println("== grid: ${o.cells.size} cells × ${o.stations.joinToString { it.label }}")
        val grid = o.cells.flatMapIndexed { i, cell ->
            val seed = o.seed * 1000 + i
            o.stations.map { run(it, cell, seed) }
        }

        println("== success rate: ${o.successRuns} seeded runs, ${o.successItems} items, ${o.successLossPercent}% loss")
        val success = o.flavours.flatMap { flavour ->
            val cell = Cell(flavour, o.successItems, o.successLossPercent)
            // Interleaved by seed, so that slow drift of a shared machine hits both ground stations alike.
            (1..o.successRuns).flatMap { k -> o.stations.map { run(it, cell, o.seed * 100_000 + k) } }
        }
        MissionResults(floor, grid, success, o)
    }
    val wall = started.elapsedNow()
    println("== done in $wall")
    val markdown = MissionReport.markdown(results, wall)
    println()
    println(markdown)
    o.json?.let { it.parentFile?.mkdirs(); it.writeText(MissionReport.json(results, wall)); println("wrote ${it.path}") }
    o.markdown?.let { it.parentFile?.mkdirs(); it.writeText(markdown); println("wrote ${it.path}") }
}

/** Everything one run of the harness measured. */
data class MissionResults(
    val floor: List<Floor>,
    val grid: List<TransferRun>,
    val success: List<TransferRun>,
    val options: MissionBenchOptions,
)
