package pod.launch

import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import pod.core.engine.Engine
import pod.core.engine.EngineEvent
import pod.core.engine.Program
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.signing.LinkSigning
import pod.mavlink.signing.SigningKeys
import pod.mavlink.platform.MavlinkPlatform
import pod.sim.SimFlavor
import java.nio.file.Path

/**
 * Runs [block] as a Dolphin program on the fleet `pod run` chose ([FleetChoice]: `--sim N` drones
 * on loopback, or `--connect ADDRESS`), printing every task and vehicle event as it happens, and
 * returns its result. Without `pod run` it flies four simulated drones in real time.
 *
 * Under `pod` (which takes over Ctrl-C and SIGTERM, see [Interruption]) a signal cancels the
 * program: every vehicle it was flying is made safe, a line says which (and whether each vehicle
 * confirmed it), and [Interrupted] is thrown. Meant for `.main.kts` scripts and small programs' `main`:
 *
 * ```
 * import pod.dsl.*
 * import pod.launch.pod
 * import pod.core.units.*
 *
 * pod {
 *     val v = pick { count(1) }[0]
 *     execute(mission("hop") { home(v.home.value!!); takeOff(20.m); move(north = 50.m); returnHomeAndLand() } on v)
 * }
 * ```
 */
public fun <T> pod(choice: FleetChoice = FleetChoice.fromSystemProperties(), print: (String) -> Unit = ::println, block: suspend Program.() -> T): T =
    runBlocking {
        val madeSafe = SafeReport()
        try {
            // Only the program is cancellable: the fleet and its link must outlive it, to make the
            // vehicles safe once it is cancelled.
            when (choice) {
                is FleetChoice.Sim -> {
                    var watch: FleetWatcher.Watch? = null
                    val onEvent: (EngineEvent) -> Unit = { e -> madeSafe.note(e); watch?.event(e) }
                    simulate(List(choice.count) { SimFlavor.ARDUCOPTER }, choice.timeScale, onLine = print, onEvent = onEvent) { sim ->
                        val program = this
                        watch = FleetWatcher.installed?.watch(sim.station, choice.timeScale, "${choice.count} simulated copters")
                        try {
                            Interruption.cancellable { runLocating(program, block) }
                        } finally {
                            watch?.close()
                        }
                    }.first
                }
                is FleetChoice.Connect -> {
                    val station = GroundStation.open(choice.address, this, signedStation(choice.keyFile))
                    val watch = try {
                        FleetWatcher.installed?.watch(station, choice.timeScale, choice.address)
                    } catch (e: Exception) {
                        station.close()
                        throw e
                    }
                    try {
                        // Against a simulator run faster, the program's durations count in its time.
                        val platform = MavlinkPlatform(station, choice.timeScale)
                        // Vehicles heard but still booting are not yet offered to `pick`: say what each lacks, once.
                        val said = HashSet<Pair<Int, String>>()
                        val booting = launch {
                            platform.initialising.collect { waiting ->
                                waiting.forEach { (id, lacks) -> if (said.add(id to lacks)) print("vehicle $id: initialising, waiting for its $lacks") }
                            }
                        }
                        // Arming and mode refusals waited out, exchanges left unanswered: said as they happen.
                        val waits = launch { showWaits(station, print) }
                        try {
                            val names = { id: Int -> platform.vehicles.value.firstOrNull { it.id == id }?.name ?: "vehicle $id" }
                            Engine(platform).runShowing(names, onLine = print, onEvent = { madeSafe.note(it); watch?.event(it) }) {
                                val program = this
                                Interruption.cancellable { runLocating(program, block) }
                            }
                        } finally {
                            booting.cancel()
                            waits.cancel()
                        }
                    } finally {
                        watch?.close()
                        station.close()
                    }
                }
            }
        } catch (e: Interrupted) {
            print(madeSafe.summary(e.signal))
            throw e
        }
    }

/** The vehicles a cancelled program made safe, as one line for the person who stopped it. */
private class SafeReport {
    private val made = java.util.concurrent.CopyOnWriteArrayList<EngineEvent.MadeSafe>()

    fun note(event: EngineEvent) {
        if (event is EngineEvent.MadeSafe) made += event
    }

    fun summary(signal: String): String {
        val (confirmed, unconfirmed) = made.partition { it.confirmed }
        return buildString {
            append("interrupted by $signal: program cancelled; ")
            if (made.isEmpty()) append("no vehicle was flying")
            if (confirmed.isNotEmpty()) append("made safe: ${confirmed.joinToString { "vehicle ${it.vehicle} (${it.state})" }}")
            if (unconfirmed.isNotEmpty()) {
                if (confirmed.isNotEmpty()) append("; ")
                append("NOT confirmed safe: ${unconfirmed.joinToString { "vehicle ${it.vehicle} (${it.state})" }}")
            }
        }
    }
}

/** A station signed with the key in [keyFile] (else `$POD_SIGNING_KEY`), or unsigned when there is neither. */
private fun signedStation(keyFile: String?): GroundStationConfig =
    GroundStationConfig(signing = SigningKeys.resolve(keyFile?.let { Path.of(it) })?.let { LinkSigning(it) })
