package pod.bench.mission

import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.long
import pod.bench.BenchCommand
import pod.bench.ReportFiles
import pod.bench.count
import pod.bench.counts
import pod.bench.duration
import pod.bench.file
import pod.bench.names
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
        /** The options [args] give (see [main] for the list). */
        fun parse(args: Array<String>): MissionBenchOptions = MissionBenchCommand().parse(args)
    }
}

/** [MissionBenchOptions] read from the command line. */
private class MissionBenchCommand : BenchCommand<MissionBenchOptions>("MissionBenchKt", "Mission transfers, Pod against MAVSDK, with loss.") {
    private val d = MissionBenchOptions()
    private val sizes by option("--sizes", help = "mission items per transfer").counts(1..5000).default(d.sizes)
    private val lossPercents by option("--losses", help = "loss each way, %").counts(0..90).default(d.lossPercents)
    private val flavours by option("--flavours").names<Autopilot>().default(d.flavours)
    private val stations by option("--stations").names<Station>().default(d.stations)
    private val successRuns by option("--success-runs").count(0..200).default(d.successRuns)
    private val successItems by option("--success-items").count(1..5000).default(d.successItems)
    private val successLossPercent by option("--success-loss").count(0..90).default(d.successLossPercent)
    private val floorSamples by option("--floor-samples").count(10..100_000).default(d.floorSamples)
    private val floorWarmUp by option("--floor-warmup").count(0..100_000).default(d.floorWarmUp)
    private val transferLimit by option("--transfer-limit").duration(1.seconds..10.minutes).default(d.limits.transfer)
    private val minTimeout by option("--min-timeout").duration(Duration.ZERO..Duration.INFINITE).default(d.timing.minTimeout)
    private val initialTimeout by option("--initial-timeout").duration(Duration.ZERO..Duration.INFINITE).default(d.timing.initialTimeout)
    private val seed by option("--seed").long().default(d.seed)
    private val python by option("--python").file().default(d.python)
    private val mavsdkScript by option("--mavsdk-script").file().default(d.mavsdkScript)
    private val mavsdkLog by option("--mavsdk-log").file()
    private val report by ReportFiles()

    override fun options(): MissionBenchOptions = MissionBenchOptions(
        sizes, lossPercents, flavours, stations, successRuns, successItems, successLossPercent, floorWarmUp, floorSamples,
        d.limits.copy(transfer = transferLimit), d.timing.copy(minTimeout = minTimeout, initialTimeout = initialTimeout),
        seed, python, mavsdkScript, mavsdkLog, report.json, report.markdown,
    )
}
