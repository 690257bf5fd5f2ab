package pod.sim.autopilot

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.units.m
import pod.mavlink.command.CommandResult
import pod.sim.flight.horizontalDistance
import kotlin.math.roundToLong

/** DO_PAUSE_CONTINUE on the simulated ArduCopter, as PauseContinue's sources describe it. */
class PauseContinueTest : StringSpec({

    "ArduCopter pauses a GUIDED goto where it is and, resumed, flies on to the same destination" {
        val ap = autopilot()
        ap.run(2.5)
        ap.mode("GUIDED")
        ap.armCommand()
        ap.command(CommandRequest(22, z = 10f))
        ap.run(8.0)
        val target = HOME.offset(north = 200.m, east = 0.m)
        val lat = (target.latitude * 1e7).roundToLong().toDouble()
        val lon = (target.longitude * 1e7).roundToLong().toDouble()
        ap.command(CommandRequest(192, param1 = -1f, x = lat, y = lon, z = 10f, frame = 6)) shouldBe CommandResult.ACCEPTED
        ap.run(5.0)
        ap.command(CommandRequest(193, param1 = 0f)) shouldBe CommandResult.ACCEPTED
        ap.run(5.0)
        val stopped = ap.body.location
        ap.run(10.0)
        horizontalDistance(ap.body.location, stopped) shouldBeLessThan 0.5
        ap.command(CommandRequest(193, param1 = 1f)) shouldBe CommandResult.ACCEPTED
        ap.modeName shouldBe "GUIDED"
        ap.run(60.0)
        horizontalDistance(ap.body.location, target) shouldBeLessThan 0.5
    }

    "ArduCopter fails a resume outside AUTO and GUIDED, saying only \"Failed to resume\" at INFO" {
        val ap = autopilot()
        ap.run(2.5)
        val out = ArrayList<SimOutput>()
        ap.command(CommandRequest(193, param1 = 1f), out) shouldBe CommandResult.FAILED
        out.filterIsInstance<SimOutput.Text>().map { it.text } shouldBe listOf("Failed to resume")
        ap.armed shouldBe false
    }
})
