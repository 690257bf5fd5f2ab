package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThan
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.withTimeout
import pod.core.time.Timebase
import pod.core.units.m
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.link.LinkConditions
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.link.TimedDatagram
import pod.sim.LinkOpener
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * MISSION_SET_CURRENT is confirmed by a MISSION_CURRENT naming the item, which the vehicle also
 * streams: for the item already current, a lost request used to look confirmed (found by the
 * queue benchmark: a re-uploaded mission whose rewritten current item was never restarted).
 */
class SetCurrentSpec : StringSpec({

    "set-current to the item being flown restarts it after an upload rewrote it, even when MISSION_SET_CURRENT never arrives" {
        runTest(timeout = 2.minutes) {
            val timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
            val network = MemoryNetwork(backgroundScope, timebase) { _, _ -> Dropping(MISSION_SET_CURRENT) }
            val gcs = GroundStation.open(network.open("udpin://127.0.0.1:0"), backgroundScope, GroundStationConfig(timebase = timebase))
            val config = SimVehicleConfig(systemId = 71).let { it.copy(gcs = "udpout://127.0.0.1:${gcs.link.localPort}", timeScale = 1.0) }
            val sim = SimVehicle(config, timebase = timebase, openLink = LinkOpener { network.open(it) })
            sim.start(backgroundScope)
            try {
                val vehicle = Flights.vehicle(gcs, 71)
                val home = SimVehicleConfig.DEFAULT_HOME
                val mission = Flights.copterSurvey(home)
                vehicle.mission.upload(mission)
                Flights.keepArmedOnGround(vehicle)
                vehicle.action.arm()
                vehicle.action.startMission()
                withTimeout(5.minutes) { vehicle.telemetry.missionCurrent.first { it == 3 } }
                val moved = home.offset((-80).m, 80.m)
                vehicle.mission.upload(mission.map { if (it.seq == 3) Flights.item(3, it.command, moved, it.z.toDouble()) else it })
                vehicle.mission.setCurrent(3)
                val target = withTimeout(30.seconds) { sim.state.first { s -> s.target?.let { it.copy(altitude = moved.altitude).distanceTo(moved).meters < 1.0 } == true } }.target!!
                target.copy(altitude = moved.altitude).distanceTo(moved).meters shouldBeLessThan 1.0
            } finally {
                sim.stop()
                gcs.close()
            }
        }
    }
}) {
    /** Loses every datagram carrying message [id] (MAVLink 1 or 2), delivers the rest at once. */
    private class Dropping(private val id: Int) : LinkConditions {
        override fun offer(bytes: ByteArray, now: Duration): List<TimedDatagram> = if (messageId(bytes) == id) emptyList() else listOf(TimedDatagram(now, bytes))

        override val nextRelease: Duration? get() = null

        override fun release(now: Duration): List<TimedDatagram> = emptyList()

        private fun messageId(b: ByteArray): Int = when {
            b.size >= 10 && b[0] == 0xFD.toByte() -> (b[7].toInt() and 0xFF) or ((b[8].toInt() and 0xFF) shl 8) or ((b[9].toInt() and 0xFF) shl 16)
            b.size >= 6 && b[0] == 0xFE.toByte() -> b[5].toInt() and 0xFF
            else -> -1
        }
    }

    private companion object {
        const val MISSION_SET_CURRENT = 41
    }
}
