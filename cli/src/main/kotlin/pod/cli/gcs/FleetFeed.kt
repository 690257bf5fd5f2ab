package pod.cli.gcs

import kotlinx.coroutines.delay
import pod.cli.json.Event
import pod.cli.json.Home
import pod.cli.json.VehicleStatus
import pod.cli.json.telemetryEvent
import pod.core.vehicle.ConnectionState
import pod.mavlink.MavlinkVehicle

/**
 * The vehicles on the link: `found` for each when first seen (and when the page opens),
 * `lost` / `regained` as their heartbeats stop and come back, and at every tick each one's
 * `telemetry`, `home` and `vehicle_status` that changed since the page last got them.
 *
 * It samples the vehicles' StateFlows once per tick rather than following every update: a page
 * showing 250 vehicles reporting at 10 Hz gets at most one state per vehicle per tick, and the
 * cost on the server is one pass over the fleet per page per tick.
 */
internal object FleetFeed : FeedPart {
    override suspend fun feed(fleet: GcsFleet, page: PageFeed) {
        val sent = HashMap<String, Event>()
        val connected = HashMap<Int, Boolean>()
        while (true) {
            for ((sysid, v) in fleet.station.vehicles.value) {
                val now = v.connection.value == ConnectionState.CONNECTED
                when (connected.put(sysid, now)) {
                    null -> page.add(found(v))
                    true -> if (!now) page.add(Event.Lost(sysid, v.identity.value.componentId, v.identity.value.type.name, v.identity.value.autopilot.name, 0))
                    false -> if (now) page.add(Event.Regained(sysid, v.identity.value.componentId, v.identity.value.type.name, v.identity.value.autopilot.name))
                }
                changed(sent, page, "telemetry:$sysid", telemetryEvent(v))
                v.telemetry.home.value?.let { h -> changed(sent, page, "home:$sysid", Home(sysid, h.latitude, h.longitude, h.altitude.meters)) }
                val text = fleet.lastText(sysid)
                changed(sent, page, "status:$sysid", VehicleStatus(sysid, v.awaiting.value?.what, text?.text, text?.severity?.name))
            }
            delay(FeedPart.TICK)
        }
    }

    private fun found(v: MavlinkVehicle): Event {
        val id = v.identity.value
        return Event.Found(id.systemId, id.componentId, id.type.name, id.autopilot.name)
    }

    private fun changed(sent: HashMap<String, Event>, page: PageFeed, key: String, event: Event) {
        if (sent.put(key, event) != event) page.latest(key, event)
    }
}
