package pod.cli.gcs

import java.util.concurrent.ConcurrentHashMap

/**
 * The surveys of one fleet (`fleet.service(SurveyDesk::class)`): per vehicle, its operator's
 * mission control and the flight serving it ([VehicleSurvey]), set up when a path is first built
 * for it and kept for as long as the fleet runs, so a page opened later shows the same survey.
 */
internal class SurveyDesk(private val fleet: GcsFleet) {
    private val surveys = ConcurrentHashMap<Int, VehicleSurvey>()

    /** Every vehicle's survey so far, by system id. */
    fun all(): Map<Int, VehicleSurvey> = surveys

    /** Vehicle [sysid]'s survey, set up (and its flight side started in the fleet's scope) on first use. */
    fun survey(sysid: Int): VehicleSurvey {
        surveys[sysid]?.let { return it }
        val vehicle = fleet.vehicle(sysid)
        return synchronized(this) {
            surveys.getOrPut(sysid) { VehicleSurvey(fleet, vehicle).also { it.start() } }
        }
    }

    /** Vehicle [sysid]'s survey, or a [GcsRequestException] when no path was ever built for it. */
    fun existing(sysid: Int): VehicleSurvey =
        surveys[sysid] ?: throw GcsRequestException("vehicle $sysid has no survey: build a path first")

    companion object {
        /** The fleet's survey desk. */
        fun of(fleet: GcsFleet): SurveyDesk = fleet.service(SurveyDesk::class) { SurveyDesk(it) }
    }
}
