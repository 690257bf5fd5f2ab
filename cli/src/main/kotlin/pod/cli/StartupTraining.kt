package pod.cli

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext
import pod.launch.Interruption
import pod.sim.SimFleet
import pod.sim.SimVehicleConfig
import java.net.DatagramSocket
import java.net.InetAddress
import kotlin.system.exitProcess

/**
 * What `./pod` runs once per build of the command (and per JVM) under
 * `-XX:ArchiveClassesAtExit`: the JVM then writes every class this run loaded into a
 * class-data-sharing archive, and each later `pod` maps them from it instead of finding, reading,
 * verifying and linking them one by one — the larger part of a command's start on JDK 17.
 *
 * So the archive holds what commands load, this runs the help (Clikt and Mordant's help
 * formatter), and a vehicle command end to end: `pod arm`, with text and with `--json` output,
 * against a simulated copter on loopback. Nothing it prints is shown.
 */
internal object StartupTraining {
    @JvmStatic
    fun main(args: Array<String>) {
        Interruption.install({ })
        val quiet = Output { }
        run(listOf("--help"), quiet, quiet, debug = false)
        run(listOf("arm", "--help"), quiet, quiet, debug = false)
        val code = runBlocking {
            val port = DatagramSocket(0, InetAddress.getLoopbackAddress()).use { it.localPort }
            val fleet = SimFleet.start(1, this, SimVehicleConfig(systemId = 1, gcs = "udpout:127.0.0.1:$port", timeScale = 40.0))
            try {
                withContext(Dispatchers.IO) {
                    val connect = listOf("--connect", "udpin:127.0.0.1:$port", "--sysid", "1", "--wait", "5s")
                    run(listOf("arm") + connect, quiet, quiet, debug = false) + run(listOf("disarm", "--json") + connect, quiet, quiet, debug = false)
                }
            } finally {
                fleet.stop()
            }
        }
        exitProcess(if (code == Exit.DONE) 0 else 1)
    }
}
