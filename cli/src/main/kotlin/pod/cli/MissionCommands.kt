package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.subcommands
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.choice
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.MavlinkVehicle
import pod.mavlink.mission.MissionException
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.TransferProgress
import pod.mavlink.mission.WplFile
import pod.mavlink.mission.WplFormatException
import java.io.IOException
import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** `pod mission`: upload, download and clear a vehicle's mission, fence or rally list. */
internal class MissionGroup(out: Output) : CliktCommand(name = "mission") {
    init {
        subcommands(MissionUpload(out), MissionDownload(out), MissionClear(out))
    }

    override fun help(context: Context): String = "Upload, download or clear a vehicle's mission, fence or rally points (QGC WPL 110 files)."

    override fun run() = Unit
}

/** Options every `pod mission` command shares, and the vehicle they pick. */
internal abstract class MissionAction(protected val out: Output, name: String) : CliktCommand(name = name) {
    private val connect by option("--connect", help = "link to the vehicle (udpin:, udpout:, tcp:)").default("udpin:0.0.0.0:14550")
    private val sysid by option("--sysid", help = "the vehicle's system id (needed when several answer)").int().restrictTo(1..255)
    protected val type by option("--type", help = "which list").choice("mission" to MissionType.MISSION, "fence" to MissionType.FENCE, "rally" to MissionType.RALLY)
        .default(MissionType.MISSION)
    protected val json by option("--json", help = "JSON lines instead of text").flag()
    private val wait by option("--wait", help = "how long to wait for the vehicle's heartbeat")
        .convert { it.toDurationOrNull() ?: fail(NOT_A_DURATION.format(it)) }.default(10.seconds)

    /** Checks local inputs (files) before any link is opened. */
    protected open fun prepare() {}

    /** Does the work with the chosen vehicle. */
    protected abstract suspend fun act(vehicle: MavlinkVehicle)

    override fun run() = runBlocking {
        prepare()
        val gcs = reportingLinkErrors { GroundStation.open(connect, this) }
        try {
            val vehicle = pick(gcs, wait)
            try {
                act(vehicle)
            } catch (e: MissionException) {
                fail(e.message ?: e.toString())
            } catch (e: pod.core.vehicle.VehicleLost) {
                fail(e.message ?: e.toString())
            }
        } finally {
            gcs.close()
        }
    }

    private suspend fun CoroutineScope.pick(gcs: GroundStation, wait: Duration): MavlinkVehicle {
        val wanted = sysid
        return try {
            withTimeout(wait) {
                if (wanted != null) {
                    gcs.vehicles.first { wanted in it }.getValue(wanted)
                } else {
                    val first = gcs.vehicles.first { it.isNotEmpty() }
                    // Give other vehicles on the link a moment to speak up before choosing.
                    kotlinx.coroutines.delay(1.5.seconds)
                    val all = gcs.vehicles.value
                    if (all.size > 1) fail("several vehicles answer (system ids ${all.keys.sorted().joinToString()}): pick one with --sysid")
                    first.values.first()
                }
            }
        } catch (e: TimeoutCancellationException) {
            fail(if (wanted != null) "no heartbeat from vehicle $wanted within $wait" else "no vehicle heard within $wait")
        }
    }

    protected fun fail(message: String): Nothing {
        if (json) out.line(jsonLine("event" to "error", "message" to message))
        throw CliktError("error: $message", statusCode = 1)
    }

    /** Reports progress: a bar redrawn in place for people at a terminal, JSON lines for scripts. */
    protected fun progress(action: String): (TransferProgress) -> Unit {
        var last = -1
        val terminal = System.console() != null
        return { p ->
            if (p.done != last) {
                last = p.done
                when {
                    json -> out.line(jsonLine("event" to "progress", "action" to action, "done" to p.done, "total" to p.total))
                    terminal -> print("\r$action ${bar(p)}")
                    p.done == p.total || p.total == 0 || p.done * 4 / p.total != (p.done - 1) * 4 / p.total ->
                        out.line("$action ${bar(p)}")
                }
            }
        }
    }

    private fun bar(p: TransferProgress): String {
        val width = 30
        val filled = if (p.total == 0) width else p.done * width / p.total
        return "[" + "#".repeat(filled) + ".".repeat(width - filled) + "] ${p.done}/${p.total}"
    }

    protected fun finish(text: String, vararg json: Pair<String, Any?>) {
        if (System.console() != null && !this.json) println()
        out.line(if (this.json) jsonLine("event" to "done", *json) else text)
    }
}

/** `pod mission upload FILE`. */
internal class MissionUpload(out: Output) : MissionAction(out, "upload") {
    private val file by argument(help = "QGC WPL 110 file")

    override fun help(context: Context): String = "Upload a QGC WPL 110 file to a vehicle."

    private var items: List<pod.mavlink.mission.MissionItem> = emptyList()

    override fun prepare() {
        items = try {
            WplFile.read(Path.of(file), type)
        } catch (e: WplFormatException) {
            fail("$file: ${e.message}")
        } catch (e: IOException) {
            fail("cannot read $file: ${e.message}")
        }
    }

    override suspend fun act(vehicle: MavlinkVehicle) {
        vehicle.mission.upload(items, type, progress("uploading"))
        finish("uploaded ${items.size} ${type.name.lowercase()} items to vehicle ${vehicle.systemId}", "action" to "upload", "items" to items.size, "sysid" to vehicle.systemId)
    }
}

/** `pod mission download FILE`. */
internal class MissionDownload(out: Output) : MissionAction(out, "download") {
    private val file by argument(help = "QGC WPL 110 file to write")

    override fun help(context: Context): String = "Download a vehicle's list into a QGC WPL 110 file."

    override suspend fun act(vehicle: MavlinkVehicle) {
        val items = vehicle.mission.download(type, progress("downloading"))
        try {
            WplFile.write(Path.of(file), items)
        } catch (e: IOException) {
            fail("cannot write $file: ${e.message}")
        }
        finish("downloaded ${items.size} ${type.name.lowercase()} items from vehicle ${vehicle.systemId} to $file", "action" to "download", "items" to items.size, "sysid" to vehicle.systemId)
    }
}

/** `pod mission clear`. */
internal class MissionClear(out: Output) : MissionAction(out, "clear") {
    override fun help(context: Context): String = "Delete a vehicle's mission, fence or rally list."

    override suspend fun act(vehicle: MavlinkVehicle) {
        vehicle.mission.clear(type)
        finish("cleared the ${type.name.lowercase()} list of vehicle ${vehicle.systemId}", "action" to "clear", "sysid" to vehicle.systemId)
    }
}
