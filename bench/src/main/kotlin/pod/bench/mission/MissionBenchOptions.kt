package pod.bench.mission

import pod.core.vehicle.Autopilot
import pod.mavlink.mission.TransferTiming
import java.io.File
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/** Command line of the mission-transfer harness; see [main]. */
data class MissionBenchOptions(
    val sizes: List<Int> = listOf(10, 100, 1000),
    val lossPercents: List<Int> = listOf(0, 10, 30),
    val flavours: List<Autopilot> = listOf(Autopilot.PX4, Autopilot.ARDUPILOT),
    val stations: List<Station> = Station.entries,
    /** Seeded runs per ground station and flavour at [successLossPercent] with [successItems] items. */
    val successRuns: Int = 20,
    val successItems: Int = 100,
    val successLossPercent: Int = 30,
    val floorWarmUp: Int = 500,
    val floorSamples: Int = 2000,
    val limits: Limits = Limits(),
    /** Pod's transfer timing (`--min-timeout`, `--initial-timeout` change it; defaults otherwise). */
    val timing: TransferTiming = TransferTiming(),
    val seed: Long = 1,
    val python: File = File(".venv/bin/python"),
    val mavsdkScript: File = File("bench/mavsdk_mission.py"),
    val mavsdkLog: File? = null,
    val json: File? = null,
    val markdown: File? = null,
) {
    val cells: List<Cell> get() = flavours.flatMap { f -> sizes.flatMap { n -> lossPercents.map { Cell(f, n, it) } } }

    companion object {
        fun parse(args: Array<String>): MissionBenchOptions {
            var o = MissionBenchOptions()
            var i = 0
            fun ints(value: String) = value.split(',').map { it.trim().toInt() }
            while (i < args.size) {
                val value = args.getOrNull(i + 1) ?: error("missing value after ${args[i]}")
                o = when (args[i]) {
                    "--sizes" -> o.copy(sizes = ints(value).onEach { require(it in 1..5000) { "sizes must be in 1..5000, was $it" } })
                    "--losses" -> o.copy(lossPercents = ints(value).onEach { require(it in 0..90) { "losses must be percentages in 0..90, was $it" } })
                    "--flavours" -> o.copy(flavours = value.split(',').map { Autopilot.valueOf(it.trim().uppercase()) })
                    "--stations" -> o.copy(stations = value.split(',').map { Station.valueOf(it.trim().uppercase()) })
                    "--success-runs" -> o.copy(successRuns = value.toInt().also { require(it in 0..200) { "success-runs must be in 0..200, was $it" } })
                    "--success-items" -> o.copy(successItems = value.toInt().also { require(it in 1..5000) })
                    "--success-loss" -> o.copy(successLossPercent = value.toInt().also { require(it in 0..90) })
                    "--floor-samples" -> o.copy(floorSamples = value.toInt().also { require(it in 10..100_000) })
                    "--floor-warmup" -> o.copy(floorWarmUp = value.toInt().also { require(it in 0..100_000) })
                    "--transfer-limit" -> o.copy(limits = o.limits.copy(transfer = Duration.parse(value).also { require(it in 1.seconds..10.minutes) }))
                    "--min-timeout" -> o.copy(timing = o.timing.copy(minTimeout = Duration.parse(value)))
                    "--initial-timeout" -> o.copy(timing = o.timing.copy(initialTimeout = Duration.parse(value)))
                    "--seed" -> o.copy(seed = value.toLong())
                    "--python" -> o.copy(python = File(value))
                    "--mavsdk-script" -> o.copy(mavsdkScript = File(value))
                    "--mavsdk-log" -> o.copy(mavsdkLog = File(value))
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
