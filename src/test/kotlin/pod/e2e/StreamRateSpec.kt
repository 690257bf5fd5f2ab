package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.maps.shouldBeEmpty
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MessageIds
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.seconds

class StreamRateSpec : StringSpec({

    "the ground station asks each vehicle it finds for its configured stream rates" {
        virtualRun { coroutineScope {
            val wanted = mapOf(33 to 10.0, 1 to 0.5)
            val gcs = station(this, GroundStationConfig(streamRates = wanted))
            val sim = vehicle(SimVehicleConfig(systemId = 9), gcs)
            try {
                // An ArduCopter streams nothing but HEARTBEAT until asked.
                sim.streamRates.value.shouldBeEmpty()
                sim.start(this)
                val rates = withTimeout(10.seconds) { sim.streamRates.first { it[33] == 10.0 && it[1] == 0.5 } }
                rates[30] shouldBe null // not asked, still off
            } finally {
                sim.stop()
                gcs.close()
            }
        } }
    }

    "an ArduCopter that is asked for nothing sends nothing but HEARTBEAT; the default station asks for what a mission needs, MISSION_CURRENT and the home included" {
        virtualRun { coroutineScope {
            val silent = station(this, GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false))
            val asking = station(this)
            val quiet = vehicle(SimVehicleConfig(systemId = 7), silent)
            val asked = vehicle(SimVehicleConfig(systemId = 8), asking)
            try {
                quiet.start(this)
                asked.start(this)
                val heard = withTimeout(10.seconds) { silent.vehicles.first { 7 in it } }.getValue(7)
                val found = withTimeout(10.seconds) { asking.vehicles.first { 8 in it } }.getValue(8)
                withTimeout(10.seconds) { found.telemetry.home.filterNotNull().first() }
                withTimeout(10.seconds) { found.telemetry.missionCurrent.filterNotNull().first() }
                val rates = withTimeout(10.seconds) { asked.streamRates.first { MessageIds.MISSION_CURRENT in it && MessageIds.GLOBAL_POSITION_INT in it } }
                rates.keys shouldBe GroundStationConfig.DEFAULT_STREAM_RATES.keys
                // Three heartbeats later the one asked for nothing has still sent nothing else.
                withTimeout(10.seconds) { heard.messages.filterNotNull().first { it.frame.messageId == 0 && heard.telemetry.linkQuality.value.received >= 4 } }
                heard.telemetry.position.value shouldBe null
                // Its home may have come once, unasked: ArduPilot sends HOME_POSITION when home is set
                // (AP_AHRS::set_home → gcs().send_message(MSG_HOME)), streamed or not.
                quiet.streamRates.value.keys.toList().shouldBeEmpty()
            } finally {
                quiet.stop()
                asked.stop()
                silent.close()
                asking.close()
            }
        } }
    }
})
