package pod.cli.gcs

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import kotlinx.serialization.builtins.ListSerializer
import kotlinx.serialization.builtins.serializer
import kotlinx.serialization.json.Json
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.CommandRejected
import pod.mavlink.telemetry.FlightModes

// The commands panel's requests: what an operator does to the selected vehicle, each through
// MavlinkVehicle.action (VehicleActions) as an app would. Each answers once the vehicle confirmed
// it (telemetry shows it armed, in the mode, at the height) and fails with the vehicle's own
// words otherwise; every one is logged for all pages ([pageAction]).

/** `{"op":"vehicle_arm","id":1,"sysid":1}`: arms, waiting out a vehicle still initialising. */
@Serializable @SerialName("vehicle_arm")
public data class VehicleArm(override val id: Long, val sysid: Int) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String? = pageAction(fleet, sysid, "arm") { it.action.arm(); "armed" }
}

/** Disarms (never forced: an autopilot refuses it in flight, and says so). */
@Serializable @SerialName("vehicle_disarm")
public data class VehicleDisarm(override val id: Long, val sysid: Int) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String? = pageAction(fleet, sysid, "disarm") { takeOver(fleet, it); it.action.disarm(); "disarmed" }
}

/** Takes off to [altM] metres above home; the vehicle must be armed. Answers once it is there. */
@Serializable @SerialName("vehicle_takeoff")
public data class VehicleTakeoff(override val id: Long, val sysid: Int, @SerialName("alt_m") val altM: Double) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String? = pageAction(fleet, sysid, "takeoff ${altM.metres()}") {
        it.action.takeoff(altM.m)
        "at ${it.telemetry.position.value?.relativeAltitude?.meters?.metres() ?: altM.metres()}"
    }
}

/** Switches to the mode called [mode] (one of [VehicleModes]' names). */
@Serializable @SerialName("vehicle_mode")
public data class VehicleMode(override val id: Long, val sysid: Int, val mode: String) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String? = pageAction(fleet, sysid, "mode $mode") { takeOver(fleet, it); it.action.setMode(mode); "in $mode" }
}

/**
 * The names of the modes vehicle [sysid] has, as a JSON array in the reply's detail: what
 * `vehicle_mode` accepts for its autopilot and airframe (ArduCopter's table, ArduPlane's, or
 * PX4's "MAIN.SUB" names; [FlightModes.names]).
 */
@Serializable @SerialName("vehicle_modes")
public data class VehicleModes(override val id: Long, val sysid: Int) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String {
        val identity = fleet.vehicle(sysid).identity.value
        return Json.encodeToString(ListSerializer(String.serializer()), FlightModes.names(identity.autopilot, identity.type))
    }
}

/**
 * Flies to [lat], [lon] at [altM] metres above home and holds there (DO_REPOSITION in the guided
 * mode). Answers once the vehicle accepted it; the map shows it going.
 */
@Serializable @SerialName("vehicle_goto")
public data class VehicleGoto(override val id: Long, val sysid: Int, val lat: Double, val lon: Double, @SerialName("alt_m") val altM: Double) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String? {
        require(lat in -90.0..90.0 && lon in -180.0..180.0) { "goto needs a valid latitude and longitude, was $lat, $lon" }
        require(altM > 0 && altM <= 10_000) { "the goto altitude must be in (0, 10000] m above home, was $altM" }
        return pageAction(fleet, sysid, String.format(java.util.Locale.ROOT, "goto %.6f, %.6f at %s", lat, lon, altM.metres())) {
            val home = it.telemetry.home.value ?: throw GcsRequestException("vehicle $sysid has reported no home yet: its altitude above home is unknown")
            takeOver(fleet, it)
            it.action.goto(Location(lat, lon, (home.altitude.meters + altM).m))
            "flying there"
        }
    }
}

/**
 * Pauses the mission, goto or queue under way, holding where the vehicle is
 * ([pod.mavlink.action.VehicleActions.pauseMission]; a queue's flight stops, its elements stay).
 */
@Serializable @SerialName("vehicle_pause")
public data class VehiclePause(override val id: Long, val sysid: Int) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String? = pageAction(fleet, sysid, "pause") { takeOver(fleet, it); it.action.pauseMission(); "holding" }
}

/**
 * Goes on with what [VehiclePause] paused: the vehicle's queue when it holds something (its
 * current element afresh), else the mission or goto ([pod.mavlink.action.VehicleActions.continueMission]).
 */
@Serializable @SerialName("vehicle_resume")
public data class VehicleResume(override val id: Long, val sysid: Int) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String? = pageAction(fleet, sysid, "resume") {
        if (fleet.queues.resume(sysid)) "flying its queue again" else it.action.continueMission().let { "going on" }
    }
}

/** Returns to launch, confirmed by the return mode. */
@Serializable @SerialName("vehicle_rtl")
public data class VehicleRtl(override val id: Long, val sysid: Int) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String? = pageAction(fleet, sysid, "RTL") { takeOver(fleet, it); it.action.returnToLaunch(); "returning" }
}

/** Lands (a multicopter where it is); answers when the landing has begun. */
@Serializable @SerialName("vehicle_land")
public data class VehicleLand(override val id: Long, val sysid: Int) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String? = pageAction(fleet, sysid, "land") { takeOver(fleet, it); it.action.land(); "landing" }
}

/**
 * Does [action] to vehicle [sysid] with [block], logging it for every page: `asked` first, then
 * `ok` with [block]'s answer or `failed` with the error (rethrown, so it becomes the reply's).
 */
internal suspend fun pageAction(fleet: GcsFleet, sysid: Int, action: String, block: suspend (MavlinkVehicle) -> String?): String? {
    val vehicle = fleet.vehicle(sysid)
    fleet.logEvent(pod.cli.json.PageAction(sysid, action, "asked"))
    val answer = try {
        block(vehicle)
    } catch (e: kotlinx.coroutines.CancellationException) {
        fleet.logEvent(pod.cli.json.PageAction(sysid, action, "failed", "stopped: the ground station is shutting down"))
        throw e
    } catch (e: CommandRejected) {
        val said = e.forPeople()
        fleet.logEvent(pod.cli.json.PageAction(sysid, action, "failed", said))
        throw GcsRequestException(said)
    } catch (e: Exception) {
        fleet.logEvent(pod.cli.json.PageAction(sysid, action, "failed", e.message ?: e::class.simpleName))
        throw e
    }
    fleet.logEvent(pod.cli.json.PageAction(sysid, action, "ok", answer))
    return answer
}

/**
 * A refusal as an operator reads it beside the button: the autopilot's reason first ("Arm: Mode
 * not armable"), then the command and the answer it got, and Pod's hint when the autopilot gave
 * no reason.
 */
private fun CommandRejected.forPeople(): String {
    val answer = result?.name ?: "MAV_RESULT $resultCode"
    val reason = statusTexts.joinToString("; ").ifEmpty { "no reason given" }
    return "$reason (${command.label.removePrefix("MAV_CMD_")}: $answer${hint?.let { "; $it" } ?: ""})"
}

/**
 * Stops the queue flight steering [vehicle], if any, before a page command takes it over: the
 * flight would otherwise send its target again within seconds and undo the command (or end,
 * seeing a mode it did not choose, as if the autopilot had taken control). The queue keeps its
 * elements; resume flies them again.
 */
private suspend fun takeOver(fleet: GcsFleet, vehicle: MavlinkVehicle) {
    fleet.queues.stopFlight(vehicle.systemId)
}

/** "20 m", "12.5 m": a height for the log. */
private fun Double.metres(): String = String.format(java.util.Locale.ROOT, "%.1f m", this).replace(".0 m", " m")
