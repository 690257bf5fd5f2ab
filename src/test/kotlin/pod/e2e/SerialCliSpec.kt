package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withTimeout
import pod.cli.Output
import pod.cli.json.Event
import pod.core.POD_VERSION
import pod.mavlink.GroundStation
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.seconds
import pod.cli.run as runPod

class SerialCliSpec : StringSpec({

    "pod sim --out serial:… puts one vehicle on a serial port, where a station finds it" {
        Socat.pair().use { pair ->
            val lines = MutableStateFlow<List<String>>(emptyList())
            coroutineScope {
                val gcs = GroundStation.open("serial://${pair.a}:57600", this)
                // pod sim runs until interrupted: this test interrupts it once the station has the vehicle.
                val sim = async(Dispatchers.IO) {
                    runInterruptible { runPod(listOf("sim", "--out", "serial://${pair.b}:57600"), Output { l -> lines.value += l }, Output { l -> lines.value += l }) }
                }
                try {
                    withTimeout(20.seconds) { lines.first { it.isNotEmpty() } }.first() shouldBe
                        "vehicle 1: quadrotor on ardupilot, on serial://${pair.b}:57600"
                    withTimeout(20.seconds) { gcs.vehicles.first { 1 in it } }
                } finally {
                    sim.cancel()
                    gcs.close()
                }
            }
        }
    }

    "pod watch --connect serial:… --json finds the vehicle on the other end of the pair" {
        Socat.pair().use { pair ->
            coroutineScope {
                val sim = SimVehicle(SimVehicleConfig(systemId = 43, gcs = "serial://${pair.b}:57600"))
                sim.start(this)
                try {
                    val out = Captured()
                    val watching = async(Dispatchers.IO) {
                        runPod(listOf("watch", "--connect", "serial://${pair.a}:57600", "--json", "--duration", "4s"), out, Output { System.err.println(it) })
                    }
                    withTimeout(20.seconds) { out.eventsOf<Event.Found>().first() }.sysid shouldBe 43
                    withTimeout(20.seconds) { watching.await() } shouldBe 0
                    out.events.take(2) shouldBe listOf(Event.PodVersion(POD_VERSION), Event.Listening("serial://${pair.a}:57600", 0))
                } finally {
                    sim.stop()
                }
            }
        }
    }

    "several vehicles on one serial port, and a device that is not there, are bad input (exit 2) naming the problem" {
        val err = mutableListOf<String>()
        runPod(listOf("sim", "--vehicles", "2", "--out", "/dev/ttyUSB0,57600"), Output { }, Output { err += it }) shouldBe 2
        err.single() shouldBe "error: --out /dev/ttyUSB0,57600: a serial port carries one simulated vehicle, not 2"
        err.clear()
        runPod(listOf("watch", "--connect", "serial:///nonexistent/pod-radio:57600", "--duration", "1s"), Output { }, Output { err += it }) shouldBe 2
        err.single() shouldBe "error: no serial device at /nonexistent/pod-radio"
        err.clear()
        runPod(listOf("arm", "--connect", "/dev/ttyUSB0,0"), Output { }, Output { err += it }) shouldBe 2
        err.single() shouldBe "error: invalid connection string '/dev/ttyUSB0,0': the baud rate must be 1..20000000, was 0"
    }
})
