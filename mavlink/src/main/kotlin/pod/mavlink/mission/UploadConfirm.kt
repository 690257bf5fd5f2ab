package pod.mavlink.mission

import pod.mavlink.protocol.Outcome
import pod.mavlink.protocol.ProtocolMachine
import pod.mavlink.protocol.Step

/**
 * An upload that ends known: a [MissionUpload] whose final MISSION_ACK never came
 * ([UploadEnd.ACK_MISSING]) goes on as a [MissionDownload] of the same list, and succeeds only if
 * the vehicle holds what was sent ([MissionStorage.holds]: ArduPilot's packed form, its item 0 —
 * home — excepted); otherwise it fails with [MissionNotConfirmed]. For a partial write only the
 * written range is compared. A pure machine like its two parts, so the property tests run this
 * policy exactly as [MissionService] does.
 */
internal class UploadConfirm(
    private val type: MissionType,
    private val items: List<MissionItem>,
    private val timing: TransferTiming,
    private val rtt: RoundTripEstimator,
    /** Null for a whole list, else the seq of the first of [items] (see [MissionUpload]). */
    private val partialFrom: Int? = null,
    /** Whether the vehicle serves downloads only in order, as far as is known ([MissionDownload]). */
    private val inOrder: Boolean = false,
    /** How the vehicle stores items: ArduPilot packs them (see [ArduPilotMissionStorage]). */
    private val ardupilot: Boolean = false,
    private val fixedWing: Boolean = false,
) : ProtocolMachine<MissionMessage, MissionMessage, Unit> {
    private val upload = MissionUpload(type, items, timing, rtt, partialFrom)

    /** The download that checks a lost acknowledgement, once one started. */
    var check: MissionDownload? = null
        private set

    /** Items the vehicle has confirmed so far. */
    val progress: TransferProgress get() = upload.progress

    override fun start(now: Long): Step<MissionMessage, Unit> = afterUpload(upload.start(now), now)

    override fun onMessage(message: MissionMessage, now: Long): Step<MissionMessage, Unit> =
        check?.let { afterCheck(it.onMessage(message, now)) } ?: afterUpload(upload.onMessage(message, now), now)

    override fun onTimer(now: Long): Step<MissionMessage, Unit> =
        check?.let { afterCheck(it.onTimer(now)) } ?: afterUpload(upload.onTimer(now), now)

    private fun afterUpload(step: Step<MissionMessage, UploadEnd>, now: Long): Step<MissionMessage, Unit> =
        when (val outcome = step.outcome) {
            null -> Step(step.send, step.wakeAt)
            is Outcome.Failed -> Step(step.send, Step.NEVER, outcome)
            is Outcome.Done -> if (outcome.value == UploadEnd.ACKNOWLEDGED) {
                Step.done(Unit, step.send)
            } else {
                val download = MissionDownload(type, timing, inOrder, rtt)
                check = download
                val first = download.start(now)
                afterCheck(Step(step.send + first.send, first.wakeAt, first.outcome))
            }
        }

    private fun afterCheck(step: Step<MissionMessage, List<MissionItem>>): Step<MissionMessage, Unit> =
        when (val outcome = step.outcome) {
            null -> Step(step.send, step.wakeAt)
            is Outcome.Failed -> Step(step.send, Step.NEVER, outcome)
            is Outcome.Done -> {
                val onBoard = outcome.value
                val written = if (partialFrom == null) onBoard else onBoard.drop(partialFrom).take(items.size)
                if (MissionStorage.holds(type, written, items, ardupilot, fixedWing, homeFirst = (partialFrom ?: 0) == 0)) {
                    Step.done(Unit, step.send)
                } else {
                    Step(step.send, Step.NEVER, Outcome.Failed(MissionNotConfirmed(type, onBoard)))
                }
            }
        }
}
