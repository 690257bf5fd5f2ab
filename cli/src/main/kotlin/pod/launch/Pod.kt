package pod.launch

import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import pod.core.engine.Engine
import pod.core.engine.Program
import pod.mavlink.GroundStation
import pod.mavlink.platform.MavlinkPlatform
import pod.samples.runShowing
import pod.samples.simulate
import pod.sim.SimFlavor

/**
 * Runs [block] as a Dolphin program on the fleet `pod run` chose ([FleetChoice]: `--sim N` drones
 * on loopback, or `--connect ADDRESS`), printing every task and vehicle event as it happens, and
 * returns its result. Without `pod run` it flies four simulated drones in real time. Meant for
 * `.main.kts` scripts and small programs' `main`:
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
fun <T> pod(choice: FleetChoice = FleetChoice.fromSystemProperties(), print: (String) -> Unit = ::println, block: suspend Program.() -> T): T =
    runBlocking {
        when (choice) {
            is FleetChoice.Sim -> simulate(List(choice.count) { SimFlavor.ARDUCOPTER }, choice.timeScale, onLine = print) { block() }.first
            is FleetChoice.Connect -> {
                val station = GroundStation.open(choice.address, this)
                try {
                    val platform = MavlinkPlatform(station)
                    // Vehicles heard but still booting are not yet offered to `pick`: say what each lacks, once.
                    val said = HashSet<Pair<Int, String>>()
                    val booting = launch {
                        platform.initialising.collect { waiting ->
                            waiting.forEach { (id, lacks) -> if (said.add(id to lacks)) print("vehicle $id: initialising, waiting for its $lacks") }
                        }
                    }
                    try {
                        Engine(platform).runShowing({ id -> platform.vehicles.value.firstOrNull { it.id == id }?.name ?: "vehicle $id" }, onLine = print, block = block)
                    } finally {
                        booting.cancel()
                    }
                } finally {
                    station.close()
                }
            }
        }
    }
