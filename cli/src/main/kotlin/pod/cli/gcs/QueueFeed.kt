package pod.cli.gcs

import kotlinx.coroutines.delay
import pod.cli.json.Event
import pod.cli.queue.toJson

/**
 * The mission queues the pages fill ([QueueDesk]): at every tick, for each vehicle that has one,
 * its `queue_status` (current entry, remaining time, pending entries) and its `queue_flight`
 * (flown or not, and why a flight ended), each only when it changed since the page got it. The
 * queue's started / ended / emptied events reach the page through the log ([LogFeed]).
 */
internal object QueueFeed : FeedPart {
    override suspend fun feed(fleet: GcsFleet, page: PageFeed) {
        val desk = fleet.queues
        val sent = HashMap<String, Event>()
        while (true) {
            for (sysid in desk.vehicles.sorted()) {
                val vehicle = fleet.station.vehicles.value[sysid] ?: continue
                val status = desk.queue(sysid).status.value.toJson()
                val t = vehicle.telemetry
                val event = Event.QueueStatus(
                    sysid, t.mode.value?.name, t.armed.value, t.position.value?.relativeAltitude?.meters,
                    status.current, status.remainingS, status.pending,
                )
                changed(sent, page, "queue:$sysid", event)
                changed(sent, page, "queue_flight:$sysid", desk.flightState(sysid))
            }
            delay(FeedPart.TICK)
        }
    }

    private fun changed(sent: HashMap<String, Event>, page: PageFeed, key: String, event: Event) {
        if (sent.put(key, event) != event) page.latest(key, event)
    }
}
