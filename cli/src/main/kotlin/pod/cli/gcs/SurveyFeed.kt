package pod.cli.gcs

import kotlinx.coroutines.delay
import pod.cli.json.Event

/**
 * The surveys, for the page: at every tick, each vehicle's `survey_state`, `survey_path` and
 * `survey_backward` that changed since the page last got them (latest only), and the forward
 * pass's `survey_photo`s it has not had yet, in the order taken (all of them for a page opened
 * late). The operator's commands and the flight's reports reach the page through the log.
 */
internal object SurveyFeed : FeedPart {
    override suspend fun feed(fleet: GcsFleet, page: PageFeed) {
        val desk = SurveyDesk.of(fleet)
        val sent = HashMap<String, Event?>()
        val photosSent = HashMap<Int, Pair<Long, Int>>() // sysid → (run, photos sent)
        while (true) {
            for ((sysid, survey) in desk.all()) {
                changed(sent, page, "survey_state:$sysid", survey.stateEvent())
                changed(sent, page, "survey_path:$sysid", survey.path)
                changed(sent, page, "survey_backward:$sysid", survey.backward)
                val photos = survey.photos
                val run = photos.firstOrNull()?.run ?: survey.run
                val (sentRun, count) = photosSent[sysid] ?: (run to 0)
                val from = if (sentRun == run) count else 0
                for (i in from until photos.size) page.add(photos[i])
                photosSent[sysid] = run to photos.size
            }
            delay(FeedPart.TICK)
        }
    }

    private fun changed(sent: HashMap<String, Event?>, page: PageFeed, key: String, event: Event?) {
        if (event == null) return
        if (sent.put(key, event) != event) page.latest(key, event)
    }
}
