package pod.cli

import pod.launch.geo.GeoFeature
import pod.launch.geo.GeoJson
import pod.launch.geo.GeoJsonException
import pod.launch.map.FlightMap
import pod.launch.map.MapFormat
import pod.launch.map.MapFormatUnknown
import pod.launch.map.MapWriteFailed
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.WplFile
import pod.mavlink.mission.WplFormatException
import pod.mavlink.plan.QgcPlan
import pod.mavlink.plan.QgcPlanFile
import pod.mavlink.plan.QgcPlanFormatException
import pod.mavlink.tlog.LoggedFlight
import pod.mavlink.tlog.TlogException
import pod.mavlink.tlog.TlogTracks
import java.io.IOException
import java.nio.charset.CharacterCodingException
import java.nio.file.Files
import java.nio.file.InvalidPathException
import java.nio.file.NoSuchFileException
import java.nio.file.Path

/** Files a command reads or writes, checked before any link opens: every problem is one [badInput] line naming the file. */
internal object LocalFiles {
    /** The items of the WPL file [name] as a [type] list. */
    fun readWpl(name: String, type: MissionType): List<MissionItem> {
        val path = path(name)
        if (Files.isDirectory(path)) badInput("$name is a directory, not a QGC WPL 110 file")
        // 65535 items of at most a few hundred characters each: anything far larger is not a WPL file.
        if (Files.isRegularFile(path) && Files.size(path) > MAX_BYTES) {
            badInput("$name is too large for a QGC WPL 110 file (${Files.size(path) / 1_048_576} MiB; a list holds at most 65535 items)")
        }
        return try {
            WplFile.read(path, type)
        } catch (e: WplFormatException) {
            badInput("$name: ${e.message}")
        } catch (e: NoSuchFileException) {
            badInput("no such file: $name")
        } catch (e: CharacterCodingException) {
            // Files.readString's MalformedInputException says only "Input length = 1".
            badInput("$name is not a QGC WPL 110 file: it is not UTF-8 text")
        } catch (e: IOException) {
            badInput("cannot read $name: ${e.message ?: e.javaClass.simpleName}")
        }
    }

    /** The plan in the QGC .plan file [name]. */
    fun readPlan(name: String): QgcPlan {
        val path = path(name)
        if (Files.isDirectory(path)) badInput("$name is a directory, not a .plan file")
        if (Files.isRegularFile(path) && Files.size(path) > MAX_BYTES) {
            badInput("$name is too large for a .plan file (${Files.size(path) / 1_048_576} MiB)")
        }
        return try {
            QgcPlanFile.read(path)
        } catch (e: QgcPlanFormatException) {
            badInput("$name: ${e.message}")
        } catch (e: NoSuchFileException) {
            badInput("no such file: $name")
        } catch (e: CharacterCodingException) {
            badInput("$name is not a .plan file: it is not UTF-8 text")
        } catch (e: IOException) {
            badInput("cannot read $name: ${e.message ?: e.javaClass.simpleName}")
        }
    }

    /** The vehicles' tracks in the tlog [name]; a log cut short or corrupt part way gives what came before, with its error. */
    fun readTracks(name: String): LoggedFlight {
        val path = tlogPath(name)
        return try {
            TlogTracks.read(path)
        } catch (e: TlogException) {
            badInput(e.message!!)
        }
    }

    /** The path of the tlog [name]: a file that exists (its contents are the reader's to check). */
    fun tlogPath(name: String): Path {
        val path = path(name)
        if (Files.isDirectory(path)) badInput("$name is a directory, not a tlog")
        if (!Files.exists(path)) badInput("no such file: $name")
        return path
    }

    /** Refuses a map to write at [name] whose extension names no map format, or that cannot be written ([checkWritable]). */
    fun checkMapOutput(name: String) {
        try {
            MapFormat.of(path(name))
        } catch (e: MapFormatUnknown) {
            badInput(e.message!!)
        }
        checkWritable(name)
    }

    /** Writes [map] to [name], in the format its extension names. */
    fun writeMap(map: FlightMap, name: String) {
        try {
            map.write(path(name))
        } catch (e: MapWriteFailed) {
            badInput(e.message!!)
        }
    }

    /** The features of the GeoJSON file [name]. */
    fun readGeoJson(name: String): List<GeoFeature> {
        val path = path(name)
        if (Files.isDirectory(path)) badInput("$name is a directory, not a GeoJSON file")
        if (Files.isRegularFile(path) && Files.size(path) > MAX_BYTES) badInput("$name is too large for a GeoJSON file Pod maps (${Files.size(path) / 1_048_576} MiB)")
        return try {
            GeoJson.read(Files.readString(path))
        } catch (e: GeoJsonException) {
            badInput("$name: ${e.message}")
        } catch (e: NoSuchFileException) {
            badInput("no such file: $name")
        } catch (e: CharacterCodingException) {
            badInput("$name is not a GeoJSON file: it is not UTF-8 text")
        } catch (e: IOException) {
            badInput("cannot read $name: ${e.message ?: e.javaClass.simpleName}")
        }
    }

    /** True when [name] names a QGC .plan file (by its extension), false for WPL. */
    fun isPlan(name: String): Boolean = name.endsWith(".plan", ignoreCase = true)

    /**
     * Refuses an output path that cannot be written: a directory, a missing or non-directory
     * parent, a read-only file or folder. Creates nothing.
     */
    fun checkWritable(name: String) {
        val path = path(name).toAbsolutePath()
        val parent = path.parent
        when {
            Files.isDirectory(path) -> badInput("cannot write $name: it is a directory")
            parent != null && !Files.exists(parent) -> badInput("cannot write $name: no such directory $parent")
            parent != null && !Files.isDirectory(parent) -> badInput("cannot write $name: $parent is not a directory")
            Files.exists(path) && !Files.isWritable(path) -> badInput("cannot write $name: the file is read-only")
            !Files.exists(path) && parent != null && !Files.isWritable(parent) -> badInput("cannot write $name: the directory $parent is read-only")
        }
    }

    private const val MAX_BYTES = 64L * 1024 * 1024

    private fun path(name: String): Path = try {
        Path.of(name)
    } catch (e: InvalidPathException) {
        badInput("'$name' is not a file path: ${e.reason}")
    }
}
