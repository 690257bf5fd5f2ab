package pod.e2e

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.longs.shouldBeInRange
import io.kotest.matchers.shouldBe
import pod.cli.json.Event
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.tlog.TlogWriter
import java.nio.file.Files
import kotlin.time.Duration.Companion.minutes

/** `pod replay --lost-after` counts silence in log time, whatever `--speed` and however the process keeps pace. */
class ReplayLostSpec : StringSpec({

    "at --speed 500 and --speed max a vehicle silent for 20 s of log is lost after --lost-after 3s of log, and the other one is not" {
        val encoder = FrameEncoder()
        val heartbeat = Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
            .baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_ACTIVE).mavlinkVersion(3).build()
        val position = GlobalPositionInt.builder().lat(411780460).lon(-85957860).alt(120000).build()
        val dir = Files.createTempDirectory("pod-replay-lost")
        val log = dir.resolve("gap.tlog")
        try {
            // 60 s of two copters: heartbeats at 1 Hz, positions at 4 Hz; vehicle 1 says nothing from 20 s to 40 s.
            TlogWriter.create(log).use { w ->
                val t0 = 1_700_000_000_000_000L
                for (tick in 0 until 240) {
                    val t = t0 + tick * 250_000L
                    for (sys in 1..2) {
                        if (sys == 1 && tick in 80 until 160) continue
                        if (tick % 4 == 0) w.write(t, encoder.encode(heartbeat, sys, 1, tick and 255))
                        w.write(t + sys, encoder.encode(position, sys, 1, tick and 255))
                    }
                }
            }
            for (speed in listOf("500", "max")) {
                val ran = pod("replay", log.toString(), "--speed", speed, "--lost-after", "3s", "--json", within = 2.minutes)
                withClue("--speed $speed: ${ran.text}") {
                    ran.code shouldBe 0
                    ran.out.map(::decodeEvent).filterIsInstance<Event.Replaying>().single().speed shouldBe speed.toDoubleOrNull()
                    val lost = ran.out.map(::decodeEvent).filterIsInstance<Event.Lost>()
                    lost.map { it.sysid } shouldBe listOf(1)
                    // Silence in log time: past 3 s, checked every 250 ms of log (not the ~50 ms of real time it took).
                    lost.single().silenceMs shouldBeInRange 3_000L..3_250L
                    ran.out.map(::decodeEvent).filterIsInstance<Event.Regained>().map { it.sysid } shouldBe listOf(1)
                }
            }
        } finally {
            dir.toFile().deleteRecursively()
        }
    }
})
