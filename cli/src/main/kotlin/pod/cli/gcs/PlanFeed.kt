package pod.cli.gcs

import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.launch
import pod.cli.json.Event

/**
 * The plans panel's state: each vehicle's latest transfer (`plan_progress`, conflated: a page
 * gets the newest per tick, not every item) and the lists it was last seen holding (`on_board`).
 * A page opened late gets both as they are.
 */
internal object PlanFeed : FeedPart {
    override suspend fun feed(fleet: GcsFleet, page: PageFeed) = coroutineScope {
        val desk = fleet.service(PlanDesk::class) { PlanDesk(it) }
        launch { follow(desk.progress, page, "plan_progress") }
        follow(desk.onBoard, page, "on_board")
    }

    /** Hands [page] each vehicle's entry of [states] when it changes (the others are not sent again). */
    private suspend fun follow(states: StateFlow<Map<Int, Event>>, page: PageFeed, kind: String) {
        var sent = emptyMap<Int, Event>()
        states.collect { all ->
            all.forEach { (sysid, event) -> if (sent[sysid] != event) page.latest("$kind:$sysid", event) }
            sent = all
        }
    }
}
