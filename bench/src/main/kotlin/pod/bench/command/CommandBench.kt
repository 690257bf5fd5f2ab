package pod.bench.command

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.runBlocking
import kotlin.time.TimeSource

/**
 * The command round trip on loopback: Pod's GroundStation (in this JVM) and pymavlink
 * (bench/pymavlink_command.py, a subprocess) as the ground station, each sending
 * MAV_CMD_SET_MESSAGE_INTERVAL to 1, 10 and 100 simulated vehicles at once and waiting for every
 * COMMAND_ACK, round after round; then 10 vehicles each behind a relay dropping 30 % each way.
 * The vehicles run in a JVM of their own ([FleetProcess]), a fresh fleet for every ground station
 * and case; within a case Pod goes first, then pymavlink.
 *
 * Usage: `CommandBenchKt [--counts 1,10,100] [--rounds 200,50,20] [--warmup 20,5,3]
 * [--lossy-count 10] [--lossy-rounds 30] [--lossy-warmup 3] [--loss 30] [--stations POD,PYMAVLINK]
 * [--gap 20ms] [--pod-warmup 200] [--python-resend 500ms] [--seed 1] [--python .venv/bin/python]
 * [--script bench/pymavlink_command.py] [--peer-log FILE] [--json FILE] [--markdown FILE]`.
 * Every wait is bounded, so the program ends by itself.
 */
fun main(args: Array<String>) {
    val o = CommandBenchOptions.parse(args)
    if (CommandStation.PYMAVLINK in o.stations) {
        require(o.python.canExecute()) { "no Python at ${o.python}: run tools/python-peers.sh" }
        require(o.script.isFile) { "no pymavlink script at ${o.script}" }
    }
    o.peerLog?.let { it.parentFile?.mkdirs(); it.writeText("") }
    val started = TimeSource.Monotonic.markNow()
    val results = runBlocking(Dispatchers.Default) {
        println("== sim fleet server (own JVM): warming up")
        val (fleet, ready) = FleetProcess.open(o.peerLog)
        val fleetReady = "${ready["warmUpSeconds"]} s, last warm-up rounds ${ready["warmUpMedianMs"]} ms median"
        println("  ready: $fleetReady")
        fleet.use {
            if (CommandStation.POD in o.stations && o.podWarmUpRounds > 0) {
                println("== Pod warm-up (discarded): 10 vehicles, ${o.podWarmUpRounds} rounds")
                println("  " + CommandReport.describe(podRun(CommandCase(10, o.podWarmUpRounds, 0), fleet, o)))
            }
            println("== cases")
            val runs = o.cases.flatMap { case ->
                o.stations.map { station ->
                    when (station) {
                        CommandStation.POD -> podRun(case, fleet, o)
                        CommandStation.PYMAVLINK -> pymavlinkRun(case, fleet, o)
                    }.also { println("  " + CommandReport.describe(it)) }
                }
            }
            CommandResults(runs, fleetReady, o)
        }
    }
    val wall = started.elapsedNow()
    println("== done in $wall")
    val markdown = CommandReport.markdown(results, wall)
    println()
    println(markdown)
    o.json?.let { it.parentFile?.mkdirs(); it.writeText(CommandReport.json(results, wall)); println("wrote ${it.path}") }
    o.markdown?.let { it.parentFile?.mkdirs(); it.writeText(markdown); println("wrote ${it.path}") }
}

/** Everything one run of the harness measured. */
data class CommandResults(val runs: List<CommandRun>, val fleetReady: String, val options: CommandBenchOptions)
