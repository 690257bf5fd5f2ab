package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldExist
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.Autopilot
import pod.mavlink.mission.WplFile
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import pod.sim.fault.LossyRelay
import java.io.File
import java.nio.file.Files
import kotlin.math.abs
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes

/**
 * `pod` stopped as a person stops it, with Ctrl-C or `kill`: a JVM of its own (`pod.cli.MainKt` on
 * this test's classpath, as the `./pod` launcher starts it) flying a simulated copter that lives
 * in this JVM, signalled with `kill -INT` / `kill -TERM`.
 */
class InterruptSpec : StringSpec({
    val cache = Files.createTempDirectory("pod-interrupt-cache").toFile()
    afterSpec { cache.deleteRecursively() }

    fun CoroutineScope.pod(vararg args: String): PodProcess = startPod(args.toList(), mapOf("POD_SCRIPT_CACHE" to cache.path))

    fun script(name: String): String = File(InterruptSpec::class.java.getResource("/scripts/$name")!!.toURI()).path

    suspend fun SimVehicle.awaitHeight(meters: Double, timeout: Duration) = withTimeout(timeout) { state.first { it.relativeAltitude.meters > meters } }

    /**
     * Safe as the brief of a hold says: in BRAKE, armed, in the air and not sinking. BRAKE may still
     * be taking out the climb when the child exits (the copter was climbing at 2.5 m/s): the vertical
     * speed is awaited, bounded; LOITER with no stick input would sink at 2.5 m/s and never settle.
     */
    suspend fun SimVehicle.shouldBeHolding(above: Double) {
        state.value.modeName shouldBe "BRAKE"
        val s = withTimeout(10.seconds) { state.first { abs(it.climbRate.metersPerSecond) < 0.5 } }
        s.modeName shouldBe "BRAKE"
        s.armed shouldBe true
        s.relativeAltitude.meters shouldBeGreaterThan above
    }

    "Ctrl-C during `pod run --connect` cancels the program, holds the copter at its height, says so and exits 130" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 71, timeScale = 5.0, gcs = "udpout://127.0.0.1:$port"))
            try {
                sim.start(this)
                val pod = pod("run", script("fly-far.main.kts"), "--connect", "udpin://127.0.0.1:$port")
                pod.awaitOut(3.minutes) { "flies 'far'" in it } // compiling the script takes most of this
                sim.awaitHeight(20.0, 60.seconds)
                pod.signal("INT")
                pod.exitCode(30.seconds) shouldBe 130
                pod.out.value shouldExist { "made safe: HOLD" in it }
                pod.out.value shouldExist { "interrupted by SIGINT" in it }
                pod.err.value.joinToString("\n") shouldContain "SIGINT"
                sim.shouldBeHolding(above = 15.0)
            } finally {
                sim.stop()
            }
        }
    }

    "SIGTERM during `pod takeoff` stops the climb and holds the copter, says so and exits 130" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 72, timeScale = 2.0, gcs = "udpout://127.0.0.1:$port"))
            try {
                sim.start(this)
                val link = arrayOf("--connect", "udpin:127.0.0.1:$port", "--sysid", "72")
                // A parked copter disarms itself after DISARM_DELAY, sooner than the child JVM starts.
                pod("param", "set", "DISARM_DELAY", "0", *link).exitCode(60.seconds) shouldBe 0
                pod("arm", *link).exitCode(60.seconds) shouldBe 0
                val pod = pod("takeoff", "60", *link)
                sim.awaitHeight(10.0, 60.seconds)
                pod.signal("TERM")
                pod.exitCode(30.seconds) shouldBe 130
                pod.out.value shouldExist { "interrupted by SIGTERM" in it && "holding in BRAKE" in it }
                sim.shouldBeHolding(above = 8.0)
                sim.state.value.relativeAltitude.meters shouldBeLessThan 50.0
            } finally {
                sim.stop()
            }
        }
    }

    "Ctrl-C during `pod mission upload` cancels the transfer, leaves the vehicle's flight alone, says so and exits 130" {
        coroutineScope {
            val port = freePort()
            // 20 ms each way: 500 items take over 20 s, long enough to be stopped half-way.
            val slow = LinkFaults(delay = 20.milliseconds)
            val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:$port", slow, slow, seed = 1)
            val file = Files.createTempFile("pod-interrupt", ".waypoints")
            try {
                relay.start(this)
                val sim = SimVehicle(SimVehicleConfig(systemId = 74, autopilot = Autopilot.PX4, gcs = "udpout://127.0.0.1:${relay.portA}"))
                try {
                    sim.start(this)
                    WplFile.write(file, waypoints(501)) // line 0 is home, which PX4 does not get: 500 items go
                    val pod = pod("mission", "upload", file.toString(), "--connect", "udpin:127.0.0.1:$port", "--sysid", "74")
                    pod.awaitOut(60.seconds) { "uploading" in it && "/500" in it && "500/500" !in it }
                    pod.signal("INT")
                    pod.exitCode(30.seconds) shouldBe 130
                    pod.out.value shouldExist { "interrupted by SIGINT: vehicle 74 transfer cancelled" in it }
                    pod.out.value.none { "500/500" in it } shouldBe true
                    sim.state.value.modeName shouldBe "AUTO.LOITER"
                    sim.state.value.armed shouldBe false
                } finally {
                    sim.stop()
                }
            } finally {
                relay.close()
                Files.deleteIfExists(file)
            }
        }
    }

    "a second Ctrl-C quits at once, without waiting for the vehicle, and says so" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 73, timeScale = 2.0, gcs = "udpout://127.0.0.1:$port"))
            try {
                sim.start(this)
                val link = arrayOf("--connect", "udpin:127.0.0.1:$port", "--sysid", "73")
                pod("param", "set", "DISARM_DELAY", "0", *link).exitCode(60.seconds) shouldBe 0
                pod("arm", *link).exitCode(60.seconds) shouldBe 0
                val pod = pod("takeoff", "60", *link)
                sim.awaitHeight(5.0, 60.seconds)
                sim.stop() // silent from now on: making it safe can only wait (3 s until it counts as lost)
                pod.signal("INT")
                withTimeout(10.seconds) { pod.err.first { lines -> lines.any { "stopping" in it } } }
                pod.signal("INT")
                pod.exitCode(2.seconds) shouldBe 130
                pod.err.value shouldExist { "SIGINT again" in it && "quitting now" in it }
            } finally {
                sim.stop()
            }
        }
    }
})
