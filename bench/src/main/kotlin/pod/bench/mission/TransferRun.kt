package pod.bench.mission

import pod.core.vehicle.Autopilot
import java.util.Locale

/** The ground stations compared. */
enum class Station(val label: String) {
    POD("Pod"),
    MAVSDK("MAVSDK"),
}

/** One grid cell: a vehicle flavour, a mission size and the loss each way on the relay. */
data class Cell(val flavour: Autopilot, val items: Int, val lossPercent: Int) {
    val loss: Double get() = lossPercent / 100.0
    val label: String get() = "${flavour.name} $items items ${lossPercent}% loss"
}

/**
 * How one timed step (upload or download) ended: [seconds] until it succeeded or failed, and for a
 * failure [error]: Pod's exception (class and message), MAVSDK's MissionRaw result name, or a timeout.
 */
data class Step(val ok: Boolean, val seconds: Double, val error: String? = null) {
    /** The short name of what went wrong, for a table cell. */
    val errorKind: String? get() = error?.takeWhile { it.isLetterOrDigit() || it == '_' }
}

/** One upload-then-download run of one ground station into a fresh vehicle behind a fresh relay. */
data class TransferRun(
    val station: Station,
    val cell: Cell,
    val seed: Long,
    /** Null when the run never got as far as uploading (vehicle not discovered, peer did not start). */
    val upload: Step?,
    /** Null when not attempted (the upload failed). */
    val download: Step?,
    /** Null when the download matched what was uploaded (or did not run), else how it differed. */
    val mismatch: String? = null,
    /** Why the run ended before uploading, if it did. */
    val setupError: String? = null,
    /** Datagrams the relay dropped vehicle → ground station and ground station → vehicle. */
    val droppedToGcs: Long = 0,
    val droppedToVehicle: Long = 0,
) {
    val uploaded: Boolean get() = upload?.ok == true
    val verified: Boolean get() = uploaded && download?.ok == true && mismatch == null
    val totalSeconds: Double? get() = if (verified) upload!!.seconds + download!!.seconds else null

    fun describe(): String = buildString {
        append(String.format(Locale.ROOT, "%-6s %-36s seed %-5d ", station.label, cell.label, seed))
        setupError?.let { append("SETUP FAILED: $it") }
        upload?.let { append("upload ${it.describe()}") }
        download?.let { append("  download ${it.describe()}") }
        mismatch?.let { append("  MISMATCH: $it") }
        append("  (relay dropped $droppedToGcs to GCS, $droppedToVehicle to vehicle)")
    }

    private fun Step.describe(): String = if (ok) String.format(Locale.ROOT, "%.3f s", seconds) else String.format(Locale.ROOT, "FAILED after %.3f s: %s", seconds, error)
}
