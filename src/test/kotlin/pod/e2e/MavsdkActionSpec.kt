package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.comparables.shouldBeLessThan
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.LandedState
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration.Companion.seconds

private const val SYSID = 11
private const val ALTITUDE = 10.0
private const val CRUISE = 8.0
private const val NORTH = 60.0

/**
 * Starts MAVSDK as a ground station listening on a loopback port (mavsdk_action.py with [args]),
 * then a simulated PX4 quadrotor sending there, and runs [block] while both run.
 */
private suspend fun mavsdkFlies(vararg args: Any, charge: Double = 1.0, block: suspend (JsonPeer, SimVehicle) -> Unit) = coroutineScope {
    val port = freeUdpPort()
    val peer = Python.startJson("mavsdk_action.py", port, 40, *args)
    val sim = SimVehicle(
        SimVehicleConfig(systemId = SYSID, autopilot = Autopilot.PX4, timeScale = 5.0, initialCharge = charge, gcs = "udpout://127.0.0.1:$port"),
    )
    try {
        withTimeout(15.seconds) { peer.await("ready") }
        sim.start(this)
        withTimeout(40.seconds) {
            val system = peer.await("system")
            system["sysid"] shouldBe "$SYSID"
            system["autopilot"] shouldBe "PX4"
            system["vehicle"] shouldBe "MULTICOPTER"
            block(peer, sim)
        }
    } finally {
        peer.stop()
        sim.stop()
    }
}

/** Waits for the peer's checkpoint [name], runs [check] on the vehicle held there, and lets the peer go on. */
private suspend fun JsonPeer.atCheckpoint(name: String, check: suspend () -> Unit) {
    await("checkpoint") { it["name"] == name }
    check()
    send("go")
}

/**
 * MAVSDK 4 as the ground station (Action, Param, Telemetry plugins) against Pod's simulated PX4:
 * what MAVSDK asks of a vehicle and how it reads the answers.
 */
class MavsdkActionSpec : StringSpec({

    "MAVSDK sets parameters, arms, takes off, flies to a point and lands a simulated PX4 quad, which does each step" {
        mavsdkFlies("flight", ALTITUDE, CRUISE, NORTH) { peer, sim ->
            val ready = peer.await("position")
            ready["fix"] shouldBe "FIX_3D"
            ready["home_amsl"]!!.toDouble() shouldBe (SimVehicleConfig.DEFAULT_HOME.altitude.meters plusOrMinus 0.01)
            ready["health_home_position_ok"] shouldBe "true"
            ready["health_global_position_ok"] shouldBe "true"
            ready["health_armable"] shouldBe "true"
            ready["health_accelerometer_calibration_ok"] shouldBe "true"

            peer.atCheckpoint("params") {
                val params = peer.events.replayCache.filter { it["event"] == "param" }
                    .map { listOf(it["op"], it["name"], it["kind"], it["result"], it["value"]).joinToString(" ") }
                params shouldBe listOf(
                    "get MPC_XY_CRUISE float SUCCESS 5.0",
                    "set MPC_XY_CRUISE float SUCCESS $CRUISE",
                    "get MPC_XY_CRUISE float SUCCESS $CRUISE",
                    "set COM_DISARM_PRFLT float SUCCESS -1.0",
                    // PX4 sends INT32 bit for bit; MAVSDK decodes it so for a PX4 autopilot.
                    "get MAV_SYS_ID int SUCCESS $SYSID",
                    "get SYS_AUTOSTART int SUCCESS 4001",
                    "set NAV_DLL_ACT int SUCCESS 2",
                    "get NAV_DLL_ACT int SUCCESS 2",
                    // MAVSDK checks the type PARAM_VALUE declares against the getter's.
                    "get MPC_XY_CRUISE int WRONG_TYPE null",
                )
            }

            peer.atCheckpoint("armed") {
                peer.await("action") { it["step"] == "set_takeoff_altitude" }["result"] shouldBe "SUCCESS"
                peer.await("action") { it["step"] == "arm" }["result"] shouldBe "SUCCESS"
                sim.state.value.armed shouldBe true
                sim.state.value.landedState shouldBe LandedState.ON_GROUND
            }

            peer.atCheckpoint("altitude") {
                peer.await("action") { it["step"] == "takeoff" }["result"] shouldBe "SUCCESS"
                // MAVSDK's takeoff leaves the altitude to MIS_TAKEOFF_ALT (default 2.5 m), which
                // set_takeoff_altitude wrote: the sim climbing to 10 m shows the write took.
                sim.state.value.relativeAltitude.meters shouldBe (ALTITUDE plusOrMinus 0.5)
                sim.state.value.landedState shouldBe LandedState.IN_AIR
            }

            val speeds = CopyOnWriteArrayList<Double>()
            val speedWatch = launch(start = CoroutineStart.UNDISPATCHED) { sim.state.collect { speeds += it.groundSpeed.metersPerSecond } }
            peer.atCheckpoint("arrived") {
                speedWatch.cancel()
                peer.await("action") { it["step"] == "goto_location" }["result"] shouldBe "SUCCESS"
                val target = SimVehicleConfig.DEFAULT_HOME.offset(NORTH.m, 0.m)
                sim.state.value.location.distanceTo(target).meters shouldBeLessThan 2.0
                sim.state.value.relativeAltitude.meters shouldBe (ALTITUDE plusOrMinus 0.5)
                // It flew at the MPC_XY_CRUISE MAVSDK wrote (the default is 5 m/s).
                speeds.max() shouldBe (CRUISE plusOrMinus 0.3)
                sim.state.value.modeName shouldBe "AUTO.LOITER"
            }

            peer.await("action") { it["step"] == "land" }["result"] shouldBe "SUCCESS"
            val landed = peer.await("landed")
            landed["in_air"] shouldBe "false"
            landed["armed"] shouldBe "false"
            landed["landed_state"] shouldBe "ON_GROUND"
            peer.await("done")
            sim.state.value.armed shouldBe false
            sim.state.value.landedState shouldBe LandedState.ON_GROUND
            sim.state.value.relativeAltitude.meters shouldBe (0.0 plusOrMinus 0.2)
        }
    }

    "MAVSDK arming a simulated PX4 with a flat battery gets COMMAND_DENIED, PX4's TEMPORARILY_REJECTED, and the reason as a status text" {
        mavsdkFlies("arm", charge = 0.05) { peer, sim ->
            peer.await("position")["fix"] shouldBe "FIX_3D"
            // MAVSDK's Action maps both MAV_RESULT_DENIED and MAV_RESULT_TEMPORARILY_REJECTED to COMMAND_DENIED.
            peer.await("action") { it["step"] == "arm" }["result"] shouldBe "COMMAND_DENIED"
            val text = peer.await("status_text") { it["text"]!!.startsWith("Arming denied") }
            text["text"] shouldBe "Arming denied: low battery"
            text["type"] shouldBe "CRITICAL"
            peer.await("arm_done")
            sim.state.value.armed shouldBe false
            withTimeout(1.seconds) { sim.statusTexts.first { it == "Arming denied: low battery" } }
        }
    }
})
