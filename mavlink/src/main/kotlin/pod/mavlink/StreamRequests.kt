package pod.mavlink

import pod.mavlink.link.LinkException
import pod.mavlink.command.CommandWire
import pod.mavlink.command.MavCommands
import pod.mavlink.command.VehicleCommand
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import pod.core.vehicle.ConnectionState

/**
 * Asks a vehicle for the telemetry a ground station needs, and keeps asking until it comes.
 *
 * ArduPilot streams nothing but HEARTBEAT until asked (its SRn_ stream rates default to 0 on
 * network links: libraries/GCS_MAVLink/GCS_MAVLink_Parameters.cpp, GCS_MAVLINK_Parameters::var_info),
 * and the requests travel without a reliable answer here, so:
 * - every rate of [GroundStationConfig.streamRates] is asked with MAV_CMD_SET_MESSAGE_INTERVAL, and
 *   asked again every [GroundStationConfig.streamRequestInterval] while its message has not been heard,
 *   up to [GroundStationConfig.streamRequestRounds] rounds;
 * - HOME_POSITION is asked at once with MAV_CMD_REQUEST_MESSAGE, and again at the same interval
 *   until the home arrives: real firmware has none until its estimator sets an origin, ~20 s after
 *   boot, and the slow HOME_POSITION stream would otherwise leave a picked vehicle without a home
 *   for seconds.
 *
 * One job per vehicle; a vehicle found again after being lost is asked again from the start
 * ([restart]), since a rebooted autopilot forgets what it was asked.
 *
 * The requests are fire-and-forget COMMAND_LONGs (confirmation 0, sent with [MavlinkVehicle.send]),
 * not exchanges of the command service ([pod.mavlink.command.CommandService]), on purpose:
 * - what confirms a request is the message arriving ([MavlinkVehicle.heardMessages], the home in
 *   telemetry, a camera in [MavlinkVehicle.payloads]), not the COMMAND_ACK: ArduPilot acknowledges
 *   SET_MESSAGE_INTERVAL (GCS_MAVLINK::handle_command_set_message_interval) and then a lost or
 *   slow stream still leaves the station without it. So the evidence that matters is awaited, and
 *   a request whose message does not come is sent again, like a resend of an unacknowledged command;
 * - every request is idempotent (a rate set twice is set; a message asked twice is sent twice), so a
 *   duplicate from a resend does no harm, and each is repeated on rediscovery anyway;
 * - the command service keeps one exchange per MAV_CMD at a time and waits up to its timeout for an
 *   answer: seven SET_MESSAGE_INTERVAL exchanges would queue behind each other, a vehicle that
 *   never acknowledges them (an old autopilot, a router in between) would hold up a program's own
 *   `setMessageInterval` for seconds, and a refusal (a message the autopilot does not stream) would
 *   be an error nobody can act on.
 * The vehicle's acknowledgements of these requests are not read. One caveat follows: while the
 * first rounds run, an ACK of a stream request can arrive during a program's own exchange of the
 * same command (SET_MESSAGE_INTERVAL, REQUEST_MESSAGE), which takes it for its answer, since an ACK
 * names only the command: that exchange may then end with the stream request's result instead of
 * its own (the same caveat holds for any two ground stations asking one vehicle).
 */
internal class StreamRequests(
    private val scope: CoroutineScope,
    private val config: GroundStationConfig,
    private val onLinkBroken: (LinkException) -> Unit,
) {
    private val jobs = HashMap<Int, Job>()

    /** Starts (or starts over) asking [vehicle]. */
    fun restart(vehicle: MavlinkVehicle) {
        val job = scope.launch(CoroutineName("stream-requests-${vehicle.systemId}")) {
            try {
                ask(vehicle)
            } catch (e: LinkException) {
                // A TCP peer that hung up: the station reports it (GroundStation.linkError); the
                // requests end with the link, they must not escape as an uncaught failure.
                onLinkBroken(e)
            }
        }
        synchronized(jobs) { jobs.put(vehicle.systemId, job) }?.cancel()
    }

    private suspend fun ask(vehicle: MavlinkVehicle) {
        vehicle.heardMessages.clear()
        var round = 0
        while (scope.isActive && vehicle.connection.value == ConnectionState.CONNECTED) {
            val homeMissing = config.requestHome && vehicle.telemetry.home.value == null
            if (homeMissing) vehicle.send(command(vehicle, MavCommands.REQUEST_MESSAGE, MessageIds.HOME_POSITION.toFloat(), 0f))
            // A vehicle with a camera answers with CAMERA_INFORMATION (see MavlinkVehicle.payloads), one
            // without refuses; asked each round like a stream, since either may be lost, and never waited for.
            val askPayloads = config.requestPayloads && round < config.streamRequestRounds && vehicle.payloads.value.isEmpty()
            if (askPayloads) vehicle.send(command(vehicle, MavCommands.REQUEST_MESSAGE, MessageIds.CAMERA_INFORMATION.toFloat(), 0f))
            val unheard = if (round < config.streamRequestRounds) config.streamRates.filterKeys { it !in vehicle.heardMessages } else emptyMap()
            for ((messageId, hz) in unheard) {
                vehicle.send(command(vehicle, MavCommands.SET_MESSAGE_INTERVAL, messageId.toFloat(), (1_000_000.0 / hz).toFloat()))
            }
            round++
            if (!homeMissing && unheard.isEmpty() && !askPayloads) return
            delay(config.streamRequestInterval)
        }
    }

    private fun command(vehicle: MavlinkVehicle, command: Int, param1: Float, param2: Float): Any {
        val id = vehicle.identity.value
        return CommandWire.encode(VehicleCommand(command, param1 = param1, param2 = param2), id.systemId, id.componentId)
    }
}
