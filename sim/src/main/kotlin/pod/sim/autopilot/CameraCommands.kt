package pod.sim.autopilot

import pod.mavlink.command.CommandResult
import pod.mavlink.command.MavCommands.DO_DIGICAM_CONTROL
import pod.mavlink.command.MavCommands.DO_SET_CAM_TRIGG_DIST
import pod.mavlink.command.MavCommands.IMAGE_START_CAPTURE
import pod.mavlink.command.MavCommands.IMAGE_STOP_CAPTURE

/**
 * The camera commands a ground station sends outside a mission (COMMAND_LONG / COMMAND_INT), as
 * ArduPilot's AP_Camera::handle_command answers them (libraries/AP_Camera/AP_Camera.cpp;
 * GCS_MAVLINK::handle_command_camera passes them on, UNSUPPORTED with no camera):
 * - IMAGE_START_CAPTURE: param1 camera id (negative: UNSUPPORTED), param2 interval in seconds,
 *   param3 count; one photo when the count is 1 or interval and count are both 0, else photos
 *   every interval, count of them (0: until stopped);
 * - IMAGE_STOP_CAPTURE stops interval triggering;
 * - DO_DIGICAM_CONTROL takes a photo when param5 (shooting command) is 1;
 * - DO_SET_CAM_TRIGG_DIST: a photo every param1 metres (0 stops), one now when param3 is 1.
 * PX4 routes IMAGE_START_CAPTURE to a MAVLink camera (component 100), which answers it; the
 * simulated vehicle answers for its built-in camera itself, the same way for every profile.
 */
internal object CameraCommands {
    /** The commands [handle] takes. */
    val HANDLED: Set<Int> = setOf(IMAGE_START_CAPTURE, IMAGE_STOP_CAPTURE, DO_DIGICAM_CONTROL, DO_SET_CAM_TRIGG_DIST)

    fun handle(ap: FlightControl, cmd: CommandRequest): CommandResult {
        if (!ap.world.camera) return CommandResult.UNSUPPORTED
        val camera = ap.camera
        when (cmd.command) {
            IMAGE_START_CAPTURE -> {
                if (cmd.param1 < 0) return CommandResult.UNSUPPORTED
                val single = cmd.param3 == 1f || (cmd.param2 == 0f && cmd.param3 == 0f)
                if (single) camera.shoot() else camera.startInterval(cmd.param2.toDouble(), cmd.param3.toInt(), ap.time)
            }
            IMAGE_STOP_CAPTURE -> {
                if (cmd.param1 < 0) return CommandResult.UNSUPPORTED
                camera.stop()
            }
            DO_DIGICAM_CONTROL -> if (cmd.x == 1.0) camera.shoot()
            DO_SET_CAM_TRIGG_DIST -> {
                camera.startDistance(cmd.param1.toDouble())
                if (cmd.param3 == 1f) camera.shoot()
            }
        }
        return CommandResult.ACCEPTED
    }
}
