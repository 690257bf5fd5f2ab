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

    "at --speed 500 a vehicle silent for 20 s of log is lost after --lost-after 3s of log, and the other one is not" {
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
            val ran = pod("replay", log.toString(), "--speed", "500", "--lost-after", "3s", "--json", within = 2.minutes)
            withClue(ran.text) {
                ran.code shouldBe 0
                val lost = ran.out.map(::decodeEvent).filterIsInstance<Event.Lost>()
                lost.map { it.sysid } shouldBe listOf(1)
                // Silence in log time: past 3 s, within the 20 s gap (not the ~50 ms of real time it took).
                lost.single().silenceMs shouldBeInRange 3_000L..20_000L
                ran.out.map(::decodeEvent).filterIsInstance<Event.Regained>().map { it.sysid } shouldBe listOf(1)
            }
        } finally {
            dir.toFile().deleteRecursively()
        }
    }
})
