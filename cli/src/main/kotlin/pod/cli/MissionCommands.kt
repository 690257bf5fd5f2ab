package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.subcommands
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.choice
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import pod.mavlink.MavlinkVehicle
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.TransferProgress
import pod.mavlink.mission.WplFile
import pod.mavlink.mission.WplFormatException
import java.io.IOException
import java.nio.file.Path

/** `pod mission`: upload, download and clear a vehicle's mission, fence or rally list. */
internal class MissionGroup(out: Output) : CliktCommand(name = "mission") {
    init {
        subcommands(MissionUpload(out), MissionDownload(out), MissionClear(out))
    }

    override fun help(context: Context): String = "Upload, download or clear a vehicle's mission, fence or rally points (QGC WPL 110 files)."

    override fun run() = Unit
}

/** Options every `pod mission` command shares, on top of picking the vehicle. */
internal abstract class MissionAction(out: Output, name: String) : VehicleCommandBase(out, name) {
    /** Interrupted, the transfer is cancelled (the vehicle is told so); the vehicle flies on as it was. */
    override suspend fun afterInterrupt(vehicle: MavlinkVehicle): String = "transfer cancelled; the vehicle's flight is unchanged"

    protected val type by option("--type", help = "which list").choice("mission" to MissionType.MISSION, "fence" to MissionType.FENCE, "rally" to MissionType.RALLY)
        .default(MissionType.MISSION)

    /**
     * Runs [transfer], reporting its progress: a [TransferProgressView] for people (a bar at a
     * terminal, a few lines elsewhere, once the total is known), a JSON line per item for scripts.
     */
    protected suspend fun <T> withProgress(action: String, transfer: suspend (onProgress: (TransferProgress) -> Unit) -> T): T {
        if (json) {
            var last = -1
            return transfer { p ->
                if (p.done != last) {
                    last = p.done
                    out.line(jsonLine("event" to "progress", "action" to action, "done" to p.done, "total" to p.total))
                }
            }
        }
        val view = TransferProgressView(out, action)
        return coroutineScope {
            val ticker = if (view.animated) launch { while (true) { delay(TransferProgressView.TICK); view.tick() } } else null
            try {
                transfer(view::update)
            } finally {
                ticker?.cancel()
                view.finish()
            }
        }
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
        withProgress("uploading") { vehicle.mission.upload(items, type, it) }
        finish("uploaded ${items.size} ${type.name.lowercase()} items to vehicle ${vehicle.systemId}", "action" to "upload", "items" to items.size, "sysid" to vehicle.systemId)
    }
}

/** `pod mission download FILE`. */
internal class MissionDownload(out: Output) : MissionAction(out, "download") {
    private val file by argument(help = "QGC WPL 110 file to write")

    override fun help(context: Context): String = "Download a vehicle's list into a QGC WPL 110 file."

    override suspend fun act(vehicle: MavlinkVehicle) {
        val items = withProgress("downloading") { vehicle.mission.download(type, it) }
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
