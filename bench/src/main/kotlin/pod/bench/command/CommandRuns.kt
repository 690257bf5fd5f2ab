package pod.bench.command

import pod.bench.percentile

/** The ground stations compared. */
enum class CommandStation(val label: String) {
    POD("Pod"),
    PYMAVLINK("pymavlink"),
}

/**
 * One measured case: [vehicles] simulated vehicles commanded at once, [rounds] measured rounds
 * after [warmUp] discarded ones, each vehicle behind its own relay dropping [lossPercent] each way
 * (no relay at all when 0).
 */
data class CommandCase(val vehicles: Int, val rounds: Int, val warmUp: Int, val lossPercent: Int = 0) {
    val label: String get() = "$vehicles vehicle${if (vehicles == 1) "" else "s"}" + if (lossPercent > 0) ", $lossPercent % loss each way" else ""
}

/**
 * One round: every vehicle sent the same command at once. [latenciesUs] per acknowledged command
 * (from the caller's send to its return, or from the first send to the ack); [makespanUs] from the
 * round's start to the last ack; [failures] commands that never were acknowledged; [sends]
 * COMMAND_LONG datagrams in all (so resends = sends − vehicles); [errors] what the failed ones threw (Pod).
 */
data class CommandRound(val latenciesUs: List<Double>, val makespanUs: Double, val failures: Int, val sends: Int, val errors: List<String> = emptyList())

/**
 * Medians of Pod's per-command time split (see [CommandTap]), over first-time-acknowledged
 * commands: the caller to Pod's link, the link's send (Ktor's datagram socket), the link's send back
 * to the ack coming out of the link's receive (kernel, relay, vehicle and Ktor's receive path), the
 * ack coming out of the link to the caller's return (station routing, the command service).
 */
data class PodSplit(val samples: Int, val toSocketUs: Double, val socketSendUs: Double, val wireUs: Double, val toCallerUs: Double)

/** Everything one ground station measured in one [case]. */
data class CommandRun(
    val station: CommandStation,
    val case: CommandCase,
    val rounds: List<CommandRound>,
    val discoverySeconds: Double? = null,
    /** Why the run never got to its rounds, if it did not. */
    val setupError: String? = null,
    val split: PodSplit? = null,
    /** Datagrams the relays dropped vehicle → ground station and back, over the whole run. */
    val droppedToGcs: Long = 0,
    val droppedToVehicle: Long = 0,
    /**
     * CPU seconds over the measured rounds (gaps included): the ground station's process (Pod: the
     * harness's JVM; pymavlink: its own process_time) and the simulated fleet's JVM.
     */
    val gcsCpuSeconds: Double? = null,
    val fleetCpuSeconds: Double? = null,
) {
    val latencies: List<Double> get() = rounds.flatMap { it.latenciesUs }
    val commands: Int get() = rounds.size * case.vehicles
    val acknowledged: Int get() = rounds.sumOf { it.latenciesUs.size }
    val failures: Int get() = rounds.sumOf { it.failures }
    val resends: Int get() = rounds.sumOf { it.sends } - commands
    val errors: List<String> get() = rounds.flatMap { it.errors }

    /** CPU µs per command of the ground station and of the fleet, over the measured rounds. */
    val gcsCpuUsPerCommand: Double get() = (gcsCpuSeconds ?: Double.NaN) * 1e6 / commands
    val fleetCpuUsPerCommand: Double get() = (fleetCpuSeconds ?: Double.NaN) * 1e6 / commands

    fun latencyMs(p: Double): Double = percentile(latencies, p) / 1000
    val maxMs: Double get() = (latencies.maxOrNull() ?: Double.NaN) / 1000
    val medianMakespanMs: Double get() = percentile(rounds.map { it.makespanUs }, 50.0) / 1000

    /** Acknowledged commands per second of commanding (rounds back to back, gaps between them left out). */
    val commandsPerSecond: Double get() = acknowledged / (rounds.sumOf { it.makespanUs } / 1e6)
}
