package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineExceptionHandler
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.job
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withTimeout
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.core.vehicle.LandedState
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.signing.LinkSigning
import pod.mavlink.signing.SigningKey
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.radio.SikRadio
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.attribute.PosixFilePermissions
import kotlin.random.Random
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * Issue 27's field link end to end, as an operator meets it: a copter behind a 57600-baud SiK
 * radio pair (an emulated radio on a socat pty pair), its link signed, `pod route` sharing it
 * between the program that flies it and `pod watch`, and the radio unplugged and plugged in again
 * mid-flight.
 */
class FieldLinkSpec : StringSpec({

    "a signed copter behind a 57600-baud radio flies its mission through pod route while pod watch shows it, the radio unplugged and back mid-flight" {
        val secret = Random(27).nextBytes(32)
        val key = SigningKey(secret.copyOf())
        val keyFile = privateKeyFile(secret)
        Socat.pair().use { radio ->
            coroutineScope {
                // A process's output readers may end with "Stream closed" when it exits: not this test's failure.
                val processes = CoroutineScope(coroutineContext + SupervisorJob(coroutineContext.job) + CoroutineExceptionHandler { _, _ -> })
                val flying = freePort()
                val watching = freePort()
                val route = processes.startPod(listOf("route", "serial://${radio.a}:57600", "udpin://127.0.0.1:$flying", "udpin://127.0.0.1:$watching"))
                val config = SimVehicleConfig(systemId = 61, timeScale = 5.0, signingKey = key, radio = SikRadio(baud = 57600))
                val sim = SimVehicle(config.copy(gcs = "serial://${radio.b}:57600"))
                // The program rides out a short outage; the watch says at once that it hears nothing.
                val gcs = GroundStation.open("udpout://127.0.0.1:$flying", this, GroundStationConfig(lostAfter = 15.seconds, signing = LinkSigning(key)))
                val watch = processes.startPod(listOf("watch", "--connect", "udpout://127.0.0.1:$watching", "--json", "--lost-after", "1s", "--key-file", keyFile.toString()))
                try {
                    sim.start(this)
                    val vehicle = Flights.vehicle(gcs, 61)
                    watch.awaitOut(1.minutes) { "\"found\"" in it && "\"sysid\":61" in it }

                    val home = config.home
                    vehicle.mission.upload(Flights.copterLeg(home, side = 150.0))
                    Flights.keepArmedOnGround(vehicle)
                    vehicle.action.arm()
                    vehicle.action.startMission()
                    withTimeout(1.minutes) { vehicle.telemetry.landedState.first { it == LandedState.IN_AIR } }
                    withTimeout(30.seconds) { watch.out.first { lines -> lines.telemetry().any { it.sysid == 61 && it.armed && (it.altRel ?: 0.0) > 5.0 } } }

                    runInterruptible(Dispatchers.IO) { radio.unplug() }
                    watch.awaitOut(30.seconds) { "\"lost\"" in it && "\"sysid\":61" in it }
                    runInterruptible(Dispatchers.IO) { radio.plugIn() }
                    watch.awaitOut(30.seconds) { "\"regained\"" in it && "\"sysid\":61" in it }

                    vehicle.action.awaitLanded(timeout = 3.minutes)
                    vehicle.telemetry.armed.value shouldBe false
                    vehicle.telemetry.position.value!!.location.distanceTo(home).meters shouldBeLessThan 3.0
                    withClue("the watch saw the copter well away from home, through the route") {
                        watch.out.value.telemetry().any { it.sysid == 61 && (it.altRel ?: 0.0) > 15.0 } shouldBe true
                    }
                    val stats = gcs.stats.value
                    withClue("signed both ways: $stats") {
                        stats.badSignatures shouldBe 0
                        stats.unsignedRefused shouldBe 0
                        stats.unsignedAccepted shouldBeGreaterThan 0 // the radio's own RADIO_STATUS, through the route
                    }
                    withClue("the radio reports reached the program through the route") { (gcs.radio.value != null) shouldBe true }
                } finally {
                    sim.stop()
                    gcs.close()
                    try {
                        stopPods(processes, watch, route)
                    } finally {
                        Files.deleteIfExists(keyFile)
                    }
                }
            }
        }
    }
})

private fun List<String>.telemetry(): List<Event.Telemetry> =
    filter { it.startsWith("{\"event\":\"telemetry\"") }.map { EventJson.decode(it) as Event.Telemetry }

/** [secret] (32 raw bytes) in a fresh file only its owner can read, as the README tells a user to keep a key. */
private fun privateKeyFile(secret: ByteArray): Path {
    val file = Files.createTempFile("pod-field-link", ".key", PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")))
    Files.write(file, secret)
    return file
}
