package pod.mavlink.workflow

import io.dronefleet.mavlink.common.CommandLong
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import pod.mavlink.GroundStationConfig
import pod.mavlink.command.CommandResult
import pod.mavlink.command.CommandWire
import pod.mavlink.command.ScriptedVehicle
import kotlin.time.Duration.Companion.seconds

/** Accepts every command and reports nothing: no photo, no rangefinder reading. */
private fun acceptingSilently(message: Any): List<Any> =
    if (message is CommandLong) listOf(CommandWire.ack(message.command().value(), CommandResult.ACCEPTED, 255, 190)) else emptyList()

class SensorWaitsTest : StringSpec({

    "a photo the vehicle accepts but never reports fails with NothingReported, not a coroutine timeout" {
        ScriptedVehicle.inVirtualTime(GroundStationConfig(streamRates = emptyMap(), requestPayloads = false), answer = ::acceptingSilently) { v, _ ->
            shouldThrow<NothingReported> { v.takePhoto(2.seconds) }.message shouldBe
                "vehicle 1 reported no photo (CAMERA_IMAGE_CAPTURED or CAMERA_FEEDBACK) after IMAGE_START_CAPTURE was accepted within 2.0 s"
        }
    }

    "a rangefinder that never reads fails with NothingReported naming DISTANCE_SENSOR" {
        ScriptedVehicle.inVirtualTime(GroundStationConfig(streamRates = emptyMap(), requestPayloads = false), answer = ::acceptingSilently) { v, _ ->
            val error = shouldThrow<NothingReported> { v.measureRange(3.seconds) }
            error.awaited shouldBe "downward rangefinder reading (DISTANCE_SENSOR)"
            error.waited shouldBe 3.seconds
        }
    }
})
