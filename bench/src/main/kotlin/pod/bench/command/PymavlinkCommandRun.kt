package pod.bench.command

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.runInterruptible
import pod.bench.PeerProcess
import kotlin.time.Duration.Companion.seconds

/** pymavlink's give-up time per command: Pod's default CommandTiming.timeout, so failures mean the same. */
private val PYTHON_GIVE_UP = 10.seconds

/**
 * bench/pymavlink_command.py as the ground station of [case], against a fresh fleet of the
 * [fleet] process: the script binds a free loopback port and reports it, the fleet starts sending
 * there, the script discovers every vehicle by its HEARTBEAT, runs the rounds and prints each
 * measured one; latencies are the script's own (time.perf_counter), so Python's start-up and
 * discovery are not counted.
 */
suspend fun pymavlinkRun(case: CommandCase, fleet: FleetProcess, o: CommandBenchOptions): CommandRun {
    val rounds = ArrayList<CommandRound>()
    fun failed(what: String) = CommandRun(CommandStation.PYMAVLINK, case, rounds, setupError = what)
    val peer = PeerProcess(
        listOf(
            o.python.path, o.script.path, "--count", case.vehicles.toString(), "--rounds", case.rounds.toString(),
            "--warmup", case.warmUp.toString(), "--gap-ms", o.gap.inWholeMilliseconds.toString(),
            "--resend-ms", o.pythonResend.inWholeMilliseconds.toString(), "--give-up-s", PYTHON_GIVE_UP.inWholeSeconds.toString(),
            "--discover-s", o.discovery.inWholeSeconds.toString(),
        ),
        "pymavlink, ${case.label}", o.peerLog,
        onOther = { e -> if (e["event"] == "round") rounds += e.toRound() },
    )
    var started = false
    try {
        val ready = runInterruptible(Dispatchers.IO) { peer.await("ready", 60.seconds) }
        val port = ready?.get("port")?.toIntOrNull() ?: return failed("pymavlink peer did not start: ${ready ?: "nothing within 60 s"}")
        fleet.start(case, o.seed, port)?.let { return failed(it) }
        started = true
        val limit = o.discovery + (PYTHON_GIVE_UP + o.gap) * (case.warmUp + case.rounds) + 30.seconds
        val discovered = runInterruptible(Dispatchers.IO) { peer.await("discovered", o.discovery + 10.seconds) }
        if (discovered?.get("event") != "discovered") return failed("vehicles not discovered: ${discovered ?: "nothing"}")
        var summary: Map<String, String>? = null
        val measuring = runInterruptible(Dispatchers.IO) { peer.await("measuring", limit) }
        if (measuring?.get("event") != "measuring") return failed("peer did not finish warming up: ${measuring ?: "nothing within $limit"}")
        val fleetCpuBefore = fleet.cpuSeconds()
        val done = runInterruptible(Dispatchers.IO) {
            peer.await("summary", limit)?.also { summary = it }?.takeIf { it["event"] != "summary" } ?: peer.await("done", 10.seconds)
        }
        if (done?.get("event") != "done") return failed("peer did not finish: ${done ?: "nothing within $limit"}")
        val fleetCpu = fleet.cpuSeconds()?.let { end -> fleetCpuBefore?.let { end - it } }
        val counters = fleet.stop()
        started = false
        return CommandRun(
            CommandStation.PYMAVLINK, case, rounds, discovered["seconds"]?.toDoubleOrNull(),
            droppedToGcs = counters["droppedToGcs"]?.toLongOrNull() ?: 0, droppedToVehicle = counters["droppedToVehicle"]?.toLongOrNull() ?: 0,
            gcsCpuSeconds = summary?.get("cpu_seconds")?.toDoubleOrNull(), fleetCpuSeconds = fleetCpu,
        )
    } finally {
        peer.close()
        if (started) fleet.stop()
    }
}

private fun Map<String, String>.toRound(): CommandRound = CommandRound(
    latenciesUs = getValue("latencies_us").split(',').filter { it.isNotBlank() }.map { it.trim().toDouble() },
    makespanUs = getValue("makespan_us").toDouble(),
    failures = getValue("failures").toInt(),
    sends = getValue("sends").toInt(),
)
