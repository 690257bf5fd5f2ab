package pod.cli.gcs

import kotlin.time.Duration.Companion.milliseconds

/**
 * One kind of thing a page is kept up to date on (the fleet, the log, queues, surveys): [feed]
 * runs for as long as the page is open, handing what changes to its [PageFeed]. It starts with the
 * current state, so a page opened late shows what one open from the start shows.
 */
public fun interface FeedPart {
    /** Feeds [page] from [fleet] until cancelled (the page closed). */
    public suspend fun feed(fleet: GcsFleet, page: PageFeed)

    public companion object {
        /** How often a page gets a batch: at most ten a second, whatever the telemetry rate. */
        public val TICK: kotlin.time.Duration = 100.milliseconds

        /** Every part a page is fed by. */
        public val ALL: List<FeedPart> = listOf(FleetFeed, LogFeed, QueueFeed, PlanFeed, SurveyFeed)
    }
}

/** The program's and the page actions' events ([GcsFleet.logEvent]), the latest first for a page opened late. */
internal object LogFeed : FeedPart {
    override suspend fun feed(fleet: GcsFleet, page: PageFeed) {
        val stop = fleet.followLog(page::add)
        try {
            kotlinx.coroutines.awaitCancellation()
        } finally {
            stop()
        }
    }
}
