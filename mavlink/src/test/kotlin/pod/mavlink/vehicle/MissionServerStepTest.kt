package pod.mavlink.vehicle

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionMessage
import pod.mavlink.mission.MissionResult
import pod.mavlink.mission.MissionType
import pod.mavlink.protocol.Step
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

private val SECOND = 1.seconds.inWholeNanoseconds

private fun waypoint(seq: Int) = MissionItem(seq, 3, 16, x = 411_780_460, y = -85_957_860, z = 20f)

/** The mission server's steps: what it answers, and when it asks its driver to wake it. */
class MissionServerStepTest : StringSpec({

    "an ArduPilot upload asks to be woken a re-request period after each request, and after 8 s of silence gives up with OPERATION_CANCELLED" {
        val server = MissionServer(MissionServerFlavor.ARDUPILOT)
        val count = server.onMessage(MissionMessage.Count(MissionType.MISSION, 2), 0)
        count.send shouldBe listOf(MissionMessage.Request(MissionType.MISSION, 0, legacy = true))
        count.wakeAt shouldBe SECOND
        server.uploading shouldBe true
        server.onTimer(SECOND).let {
            it.send shouldBe listOf(MissionMessage.Request(MissionType.MISSION, 0, legacy = true))
            it.wakeAt shouldBe 2 * SECOND
        }
        server.onTimer(8 * SECOND).let {
            it.send shouldBe listOf(MissionMessage.Ack(MissionType.MISSION, MissionResult.OPERATION_CANCELLED))
            it.wakeAt shouldBe Step.NEVER
        }
        server.uploading shouldBe false
    }

    "a PX4 upload re-requests every 250 ms, gives up silently after 5 s, and a completed upload stops the timer" {
        val server = MissionServer(MissionServerFlavor.PX4)
        server.onMessage(MissionMessage.Count(MissionType.MISSION, 1), 0).wakeAt shouldBe 250.milliseconds.inWholeNanoseconds
        server.onTimer(5 * SECOND).let {
            it.send shouldBe emptyList()
            it.wakeAt shouldBe Step.NEVER
        }
        server.onMessage(MissionMessage.Count(MissionType.MISSION, 1), 6 * SECOND)
        server.onMessage(MissionMessage.Item(waypoint(0)), 6 * SECOND + 1).let {
            it.send shouldBe listOf(MissionMessage.Ack(MissionType.MISSION, MissionResult.ACCEPTED))
            it.wakeAt shouldBe Step.NEVER
        }
        server.list(MissionType.MISSION) shouldBe listOf(waypoint(0))
    }

    "a message that does not touch the upload repeats the wake time, so the driver keeps its timer" {
        val server = MissionServer(MissionServerFlavor.ARDUPILOT)
        val wake = server.onMessage(MissionMessage.Count(MissionType.MISSION, 3), 0).wakeAt
        server.onMessage(MissionMessage.SetCurrent(0), 100).wakeAt shouldBe wake
        server.onMessage(MissionMessage.RequestList(MissionType.MISSION), 200).let {
            it.send shouldBe listOf(MissionMessage.Ack(MissionType.MISSION, MissionResult.DENIED))
            it.wakeAt shouldBe wake
        }
    }

    "clearing asks the vehicle, given at construction, and a refusal is MISSION_ACK ERROR" {
        var flying = true
        val server = MissionServer(MissionServerFlavor.ARDUPILOT, clearAllowed = { type -> type != MissionType.MISSION || !flying })
        server.load(MissionType.MISSION, listOf(waypoint(0)))
        server.onMessage(MissionMessage.ClearAll(MissionType.MISSION), 0).send shouldBe listOf(MissionMessage.Ack(MissionType.MISSION, MissionResult.ERROR))
        server.onMessage(MissionMessage.ClearAll(MissionType.FENCE), 0).send shouldBe listOf(MissionMessage.Ack(MissionType.FENCE, MissionResult.ACCEPTED))
        flying = false
        server.onMessage(MissionMessage.ClearAll(MissionType.MISSION), 0).send shouldBe listOf(MissionMessage.Ack(MissionType.MISSION, MissionResult.ACCEPTED))
        server.list(MissionType.MISSION) shouldBe emptyList()
    }

    "right after boot an ArduPilot server answers a non-empty MISSION_COUNT with NO_SPACE until its storage is ready" {
        val server = MissionServer(MissionServerFlavor.ARDUPILOT, storageReadyAt = 3 * SECOND)
        server.onMessage(MissionMessage.Count(MissionType.MISSION, 1), SECOND).send shouldBe listOf(MissionMessage.Ack(MissionType.MISSION, MissionResult.NO_SPACE))
        server.onMessage(MissionMessage.Count(MissionType.MISSION, 1), 3 * SECOND).send shouldBe listOf(MissionMessage.Request(MissionType.MISSION, 0, legacy = true))
    }
})
