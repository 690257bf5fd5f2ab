package pod.mavlink

import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.TestScope
import pod.core.time.Timebase
import pod.mavlink.codec.FrameEncoder

/** The test scheduler's clock and a dispatcher on it: a station or vehicle on it runs in virtual time. */
internal fun TestScope.virtualTimebase(): Timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))

private val encoder = FrameEncoder()

/** An ArduCopter quadrotor's HEARTBEAT frame from [systemId] (component 1), standing by. */
internal fun copterHeartbeat(systemId: Int, sequence: Int): ByteArray = encoder.encode(
    Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
        .baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_STANDBY).mavlinkVersion(3).build(),
    systemId, 1, sequence and 255,
)
