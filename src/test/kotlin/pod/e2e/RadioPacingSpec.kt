package pod.e2e

import io.dronefleet.mavlink.common.MavParamType
import io.dronefleet.mavlink.common.ParamSet
import io.dronefleet.mavlink.common.ParamValue
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.ints.shouldBeInRange
import io.kotest.matchers.ints.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.mission.MissionType
import pod.mavlink.radio.RadioPacing
import pod.mavlink.radio.RadioStatus
import pod.mavlink.tlog.FrameDirection
import pod.mavlink.tlog.FrameTap
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.radio.SikRadio
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * A ground station behind an emulated 57600-baud SiK radio pair, in virtual time: the radio's
 * RADIO_STATUS reaches [GroundStation.radio], and pacing on its reports is what keeps a burst of
 * traffic from overflowing the ground radio's 2048-byte buffer.
 */
class RadioPacingSpec : StringSpec({

    "the ground radio's RADIO_STATUS is parsed into the station's radio, from SiK's ids, with its buffer empty at rest" {
        virtualRun(seed = 5) {
            behindRadio(GroundStationConfig()) { gcs, _, sim ->
                val report = withTimeout(5.seconds) { gcs.radio.filterNotNull().first() }
                report.systemId shouldBe RadioStatus.SIK_SYSTEM_ID
                report.componentId shouldBe RadioStatus.SIK_COMPONENT_ID
                report.txbuf shouldBe 100
                report.rssi shouldBeInRange 177..183
                report.remnoise shouldBeInRange 35..41
                sim.radioLink!!.reports shouldBeGreaterThan 0
            }
        }
    }

    "paced, a 200-item upload and a 300-step parameter sweep cross a 57600-baud radio without a byte dropped" {
        virtualRun(seed = 5) {
            behindRadio(GroundStationConfig()) { gcs, vehicle, sim ->
                withTimeout(5.seconds) { gcs.radio.filterNotNull().first() }
                val echoes = burst(gcs, vehicle, sim)
                sim.radioLink!!.uplinkDropped shouldBe 0
                echoes shouldBe SWEEP
                vehicle.params.read("WPNAV_SPEED").value shouldBe (FIRST_SPEED + SWEEP - 1).toDouble()
            }
        }
    }

    "paced, a 200-item upload sends each item once: its resend timer waits a radio's round trip, not loopback's" {
        virtualRun(seed = 5) {
            behindRadio(GroundStationConfig()) { gcs, vehicle, sim ->
                withTimeout(5.seconds) { gcs.radio.filterNotNull().first() }
                val sent = AtomicInteger()
                val recording = gcs.record(
                    FrameTap { _, direction, frame -> if (direction == FrameDirection.SENT && frame.messageId() == MISSION_ITEM_INT) sent.incrementAndGet() },
                )
                withTimeout(2.minutes) { vehicle.mission.upload(waypoints(200)) }
                recording.stop()
                // The vehicle asks for every item once; an item sent again is a resend fired early.
                sent.get() shouldBeLessThanOrEqual 205
                sim.radioLink!!.uplinkDropped shouldBe 0
            }
        }
    }

    "unpaced, the same burst overflows the ground radio's buffer" {
        virtualRun(seed = 5) {
            behindRadio(GroundStationConfig(radioPacing = RadioPacing.Off)) { gcs, vehicle, sim ->
                withTimeout(5.seconds) { gcs.radio.filterNotNull().first() }
                val echoes = burst(gcs, vehicle, sim)
                sim.radioLink!!.uplinkDropped shouldBeGreaterThan 1000
                (echoes < SWEEP) shouldBe true
            }
        }
    }

    "reports move on while pacing is off: the station still shows the radio" {
        virtualRun(seed = 6) {
            behindRadio(GroundStationConfig(radioPacing = RadioPacing.Off)) { gcs, _, _ ->
                withTimeout(5.seconds) { gcs.radio.filterNotNull().first() } shouldNotBe null
            }
        }
    }
})

private const val SWEEP = 300
private const val MISSION_ITEM_INT = 73

/** A MAVLink 2 frame's message id (bytes 7..9, little-endian). */
private fun ByteArray.messageId(): Int = (this[7].toInt() and 0xFF) or ((this[8].toInt() and 0xFF) shl 8) or ((this[9].toInt() and 0xFF) shl 16)
private const val FIRST_SPEED = 500

/**
 * The burst: a 200-item mission upload while WPNAV_SPEED is swept through [SWEEP] values with
 * PARAM_SET sent back to back (as a tuning script or a parameter-file push sends them). Returns
 * how many of the sweep's PARAM_VALUE echoes came back. Paced, the upload must also arrive whole
 * (checked here against what the vehicle holds); unpaced, it may or may not survive the losses.
 */
private suspend fun VirtualFleet.burst(gcs: GroundStation, vehicle: MavlinkVehicle, sim: SimVehicle): Int = coroutineScope {
    val echoes = AtomicInteger()
    val counting = launch(start = CoroutineStart.UNDISPATCHED) {
        vehicle.messages.collect { m -> if ((m.message as? ParamValue)?.paramId()?.trimEnd('\u0000') == "WPNAV_SPEED") echoes.incrementAndGet() }
    }
    val items = waypoints(200)
    val upload = async { runCatching { withTimeout(2.minutes) { vehicle.mission.upload(items) } } }
    for (i in 0 until SWEEP) {
        gcs.send(
            ParamSet.builder().targetSystem(vehicle.identity.value.systemId).targetComponent(1).paramId("WPNAV_SPEED")
                .paramValue((FIRST_SPEED + i).toFloat()).paramType(EnumValue.of(MavParamType.MAV_PARAM_TYPE_REAL32)).build(),
        )
    }
    val uploaded = upload.await()
    if (gcs.config.radioPacing.enabled) {
        uploaded.isSuccess shouldBe true
        sim.missionServer.list(MissionType.MISSION).size shouldBe items.size
    }
    // Let every echo still on its way cross the radio (a few seconds of virtual time).
    kotlinx.coroutines.delay(5.seconds)
    counting.cancel()
    echoes.get()
}

/** A station configured by [config] and one ArduCopter behind a 57600-baud SiK pair; [block] once the station knows the vehicle. */
private suspend fun VirtualFleet.behindRadio(
    config: GroundStationConfig,
    block: suspend (GroundStation, MavlinkVehicle, SimVehicle) -> Unit,
) = coroutineScope {
    val gcs = station(this, config)
    val sim = vehicle(SimVehicleConfig(systemId = 31, radio = SikRadio(baud = 57_600, seed = seed)), gcs)
    try {
        sim.start(this)
        val vehicle = withTimeout(10.seconds) { gcs.vehicles.first { 31 in it } }.getValue(31)
        block(gcs, vehicle, sim)
    } finally {
        sim.stop()
        gcs.close()
    }
}
