package pod.cli.json

import pod.core.engine.EngineEvent
import pod.core.platform.MissionEvent
import pod.core.vehicle.ConnectionState
import pod.mavlink.FleetEvent
import pod.mavlink.MavlinkVehicle
import pod.mavlink.radio.RadioStatus
import pod.cli.queue.toJson

// Pod's own objects as the events `--json` prints: the model stays free of them, and each
// conversion picks the fields a script needs (never an object's toString()).

/** The `found`, `lost` or `regained` event of a fleet change. */
internal fun FleetEvent.toEvent(): Event {
    val id = vehicle.identity.value
    val type = id.type.name
    val autopilot = id.autopilot.name
    return when (this) {
        is FleetEvent.Found -> Event.Found(id.systemId, id.componentId, type, autopilot)
        is FleetEvent.Lost -> Event.Lost(id.systemId, id.componentId, type, autopilot, silence.inWholeMilliseconds)
        is FleetEvent.Regained -> Event.Regained(id.systemId, id.componentId, type, autopilot)
    }
}

/** The `telemetry` event: what [vehicle] last reported. */
/** A radio's report as `pod watch --json` prints it. */
internal fun radioEvent(r: RadioStatus): Event.Radio = Event.Radio(r.systemId, r.componentId, r.rssi, r.remrssi, r.noise, r.remnoise, r.txbuf, r.rxerrors, r.fixed)

internal fun telemetryEvent(vehicle: MavlinkVehicle): Event.Telemetry {
    val t = vehicle.telemetry
    val pos = t.position.value
    val battery = t.battery.value
    val gps = t.gps.value
    val link = t.linkQuality.value
    return Event.Telemetry(
        sysid = vehicle.systemId,
        connected = vehicle.connection.value == ConnectionState.CONNECTED,
        lat = pos?.location?.latitude, lon = pos?.location?.longitude,
        altMsl = pos?.location?.altitude?.meters, altRel = pos?.relativeAltitude?.meters,
        heading = pos?.heading?.degrees,
        battery = battery?.remaining, voltage = battery?.voltage,
        mode = t.mode.value?.name, armed = t.armed.value, landed = t.landedState.value.name,
        gpsFix = gps?.fix?.name, satellites = gps?.satellites,
        link = link.fraction, lostFrames = link.lost,
    )
}

/** A program's event as printed by `pod demo --json`, or null for one it does not print (a step starting, the program's end). */
internal fun EngineEvent.toEvent(): Event? {
    val at = at.inWholeMilliseconds / 1000.0
    return when (this) {
        is EngineEvent.TaskStarted -> Event.TaskStarted(at, id, parent, label, vehicles)
        is EngineEvent.TaskCompleted -> Event.TaskDone(at, id, label)
        is EngineEvent.TaskFailed -> Event.TaskFailed(at, id, label, error.message ?: error::class.simpleName ?: "failed")
        is EngineEvent.TaskCancelled -> Event.TaskCancelled(at, id, label)
        is EngineEvent.Flying -> Event.Flying(at, task, vehicle, mission.name, mission.steps.size)
        is EngineEvent.Mission -> when (val e = event) {
            is MissionEvent.Uploaded -> Event.Mission(at, task, vehicle, "uploaded", step = null, steps = e.steps)
            is MissionEvent.Prepared -> Event.Mission(at, task, vehicle, "prepared", step = null, steps = null, changes = e.changes)
            MissionEvent.Started -> Event.Mission(at, task, vehicle, "started", step = null, steps = null)
            is MissionEvent.StepStarted -> null
            is MissionEvent.StepDone -> Event.Mission(at, task, vehicle, "step_done", step = e.step, steps = null)
            is MissionEvent.Loitering -> Event.Mission(at, task, vehicle, "loitering", step = e.step, steps = null)
            MissionEvent.Completed -> Event.Mission(at, task, vehicle, "completed", step = null, steps = null)
        }
        // The queue's own events, in the words `pod queue serve` prints them (at_s: the queue's time).
        is EngineEvent.Queue -> queueEvent(vehicle, event)
        is EngineEvent.MadeSafe -> Event.MadeSafe(at, vehicle, state.name, confirmed)
        is EngineEvent.Picked -> Event.Picked(at, vehicles)
        is EngineEvent.Released -> Event.Released(at, vehicles)
        is EngineEvent.Message -> Event.Message(at, text)
        // runShowing stops before it: the JSON lines end with the program's last task, as before.
        is EngineEvent.ProgramEnded -> null
    }
}

/** [event] of vehicle [sysid]'s queue as `pod queue serve` prints it. */
internal fun queueEvent(sysid: Int, event: pod.core.queue.QueueEvent): Event {
    val at = event.at.inWholeMilliseconds / 1000.0
    return when (event) {
        is pod.core.queue.QueueEvent.Started -> Event.QueueStarted(at, sysid, event.entry.toJson())
        is pod.core.queue.QueueEvent.Ended -> Event.QueueEnded(at, sysid, event.entry.toJson(), event.reason.name.lowercase())
        is pod.core.queue.QueueEvent.Emptied -> Event.QueueEmptied(at, sysid)
    }
}
