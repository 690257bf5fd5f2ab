package pod.cli.json

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import pod.cli.queue.EntryJson

/**
 * One line of `pod … --json` output: a JSON object whose `event` field names the kind. Every
 * field of a kind is always printed (`null` when unknown or not applicable), in the order
 * declared here; field names are snake_case. Encode and decode with [EventJson].
 *
 * Units: times in seconds unless the name says `_ms`; latitudes and longitudes in degrees;
 * altitudes in metres; fractions (battery, link) from 0 to 1. A number that is not finite is
 * written as `null`.
 */
@Serializable
public sealed interface Event {

    /**
     * The first line of every `pod … --json` run: the [version] of Pod printing it
     * ([pod.core.POD_VERSION]), so a reader knows which model the lines that follow are in.
     */
    @Serializable @SerialName("pod")
    public data class PodVersion(val version: String) : Event

    // ---- pod watch, pod demo: the fleet on a link ----

    /**
     * `pod watch` opened its link: [address] as given, [port] the local UDP or TCP port. `pod queue
     * serve` opened its control endpoint: [address] is HOST:PORT, [port] the port it got.
     */
    @Serializable @SerialName("listening")
    public data class Listening(val address: String, val port: Int) : Event

    /** A vehicle was heard for the first time. [type] and [autopilot] are Pod's enum names (QUADROTOR, ARDUPILOT…). */
    @Serializable @SerialName("found")
    public data class Found(val sysid: Int, val compid: Int, val type: String, val autopilot: String) : Event

    /** A vehicle has been silent for [silenceMs] milliseconds (`--lost-after`). */
    @Serializable @SerialName("lost")
    public data class Lost(
        val sysid: Int,
        val compid: Int,
        val type: String,
        val autopilot: String,
        @SerialName("silence_ms") val silenceMs: Long,
    ) : Event

    /** A lost vehicle is heard again. */
    @Serializable @SerialName("regained")
    public data class Regained(val sysid: Int, val compid: Int, val type: String, val autopilot: String) : Event

    /**
     * A vehicle's latest state, once per vehicle per period. Position fields are null until the
     * vehicle reports a position; [gpsFix] names MAVLink's GPS_FIX_TYPE (`FIX_3D`), null outside it; [link] the fraction of its
     * frames that arrived and [lostFrames] how many did not.
     */
    @Serializable @SerialName("telemetry")
    public data class Telemetry(
        val sysid: Int,
        val connected: Boolean,
        val lat: Finite?,
        val lon: Finite?,
        @SerialName("alt_msl") val altMsl: Finite?,
        @SerialName("alt_rel") val altRel: Finite?,
        val heading: Finite?,
        val battery: Finite?,
        val voltage: Finite?,
        val mode: String?,
        val armed: Boolean,
        val landed: String,
        @SerialName("gps_fix") val gpsFix: String?,
        val satellites: Int?,
        val link: Finite?,
        @SerialName("lost_frames") val lostFrames: Long,
    ) : Event

    /**
     * The latest RADIO_STATUS a telemetry radio on the link injected (a SiK radio reports as
     * sysid 51, compid 68), once per period while one has been heard: its signal strengths and
     * noise in the radio's own units (0..254, 255 unknown; remote: the other radio's), [txbuf] the
     * free part of its transmit buffer in percent, [rxerrors] and [fixed] its air packets received
     * with errors and repaired since it booted.
     */
    @Serializable @SerialName("radio")
    public data class Radio(
        val sysid: Int,
        val compid: Int,
        val rssi: Int,
        val remrssi: Int,
        val noise: Int,
        val remnoise: Int,
        val txbuf: Int,
        val rxerrors: Int,
        val fixed: Int,
    ) : Event

    // ---- pod replay ----

    /** `pod replay` started playing [file] at [speed] times the recorded pace; null with `--speed max` (unpaced). */
    @Serializable @SerialName("replaying")
    public data class Replaying(val file: String, val speed: Finite?) : Event

    /**
     * `pod replay` ended: [records] played, covering [logS] seconds of the log; [error] says why the
     * log ended early (a record cut short or corrupt), null when it was played to its end; [map] is
     * the map written, if asked. The last line.
     */
    @Serializable @SerialName("replay_done")
    public data class ReplayDone(
        val records: Long,
        @SerialName("log_s") val logS: Finite,
        val error: String?,
        val map: String?,
    ) : Event

    // ---- pod sim ----

    /** `pod sim` started a vehicle that sends from [localPort] (null before its socket is bound) to [out]. */
    @Serializable @SerialName("started")
    public data class Started(
        val sysid: Int,
        val type: String,
        val autopilot: String,
        @SerialName("local_port") val localPort: Int?,
        val out: String,
    ) : Event

    // ---- commands to one vehicle (arm, takeoff, mission …, param …) ----

    /**
     * The command waits and says for what ([reason]): a vehicle not ready yet (`arm`, once per
     * reason), a `heartbeat` while picking the vehicle ([sysid] null when any will do; [heard] the
     * system ids heard so far), or an answer the vehicle has not given yet while Pod resends
     * ([attempt]). [waitedS] is how long it has waited, [timeoutS] when it gives up, in seconds.
     */
    @Serializable @SerialName("waiting")
    public data class Waiting(
        val sysid: Int?,
        @SerialName("for") val reason: String,
        val heard: List<Int>? = null,
        val attempt: Int? = null,
        @SerialName("waited_s") val waitedS: Finite? = null,
        @SerialName("timeout_s") val timeoutS: Finite? = null,
    ) : Event

    /** A mission transfer moved on: [done] of [total] items ([action] is `uploading` or `downloading`). */
    @Serializable @SerialName("progress")
    public data class Progress(val action: String, val done: Int, val total: Int) : Event

    /**
     * The command did what was asked; the last line. [action] names the command (`arm`, `takeoff`,
     * `upload`, `param-set`…). [mode], [armed] and [relativeAltM] are the vehicle's state as the
     * command ends; [items] is the list's size after a mission command; [name], [value] and [type]
     * are the parameter of `param get` / `param set`, as the vehicle reports it, and [requested] the
     * value `param set` asked for (an integer parameter stores it rounded). Fields a command
     * does not concern are null.
     */
    @Serializable @SerialName("done")
    public data class Done(
        val action: String,
        val sysid: Int,
        val mode: String?,
        val armed: Boolean?,
        @SerialName("relative_alt_m") val relativeAltM: Finite?,
        val items: Int? = null,
        val name: String? = null,
        val value: Finite? = null,
        val type: String? = null,
        val requested: Finite? = null,
    ) : Event

    /**
     * The command failed: the vehicle refused, did not answer or was lost (exit 1), or its arguments or
     * files were bad (exit 2; then it is the only line). The same [message] goes to stderr.
     */
    @Serializable @SerialName("error")
    public data class Error(val message: String) : Event

    /** Something in an input file Pod read but changed or could not keep (a .plan's survey read as its expanded items); the command goes on. */
    @Serializable @SerialName("warning")
    public data class Warning(val message: String) : Event

    /**
     * Ctrl-C or SIGTERM stopped the command ([signal] is `SIGINT` or `SIGTERM`). For a vehicle
     * command: [safe] says whether the vehicle confirmed the safe state described by [state], and
     * [mode], [armed], [relativeAltM] are what it last reported. For `pod demo`: [map] is the SVG
     * written so far and the vehicle fields are null.
     */
    @Serializable @SerialName("interrupted")
    public data class Interrupted(
        val signal: String,
        val sysid: Int? = null,
        val safe: Boolean? = null,
        val state: String? = null,
        val mode: String? = null,
        val armed: Boolean? = null,
        @SerialName("relative_alt_m") val relativeAltM: Finite? = null,
        val map: String? = null,
    ) : Event

    // ---- pod queue: a vehicle's mission queue; entries and statuses as pod.cli.queue's JSON ----

    /**
     * `pod queue serve` flies vehicle [sysid]'s queue from now on (after `--takeoff`, if asked) and
     * takes `pod queue` requests on [control] (HOST:PORT); [mode] and [relativeAltM] as the flight begins.
     */
    @Serializable @SerialName("queue_serving")
    public data class QueueServing(
        val sysid: Int,
        val control: String,
        val mode: String?,
        @SerialName("relative_alt_m") val relativeAltM: Finite?,
    ) : Event

    /** [entry] of vehicle [sysid]'s queue became current; [atS] is the queue's time in seconds. */
    @Serializable @SerialName("queue_started")
    public data class QueueStarted(@SerialName("at_s") val atS: Double, val sysid: Int, val entry: EntryJson) : Event

    /**
     * [entry] stopped being current, for [reason]: `arrived`, `elapsed` (its duration ran out),
     * `skipped` (`next`), `preempted` (a prepend; it is pending again), `replaced` or `cleared`.
     */
    @Serializable @SerialName("queue_ended")
    public data class QueueEnded(@SerialName("at_s") val atS: Double, val sysid: Int, val entry: EntryJson, val reason: String) : Event

    /** Vehicle [sysid]'s queue ran empty: the vehicle holds where it is, at its height. */
    @Serializable @SerialName("queue_emptied")
    public data class QueueEmptied(@SerialName("at_s") val atS: Double, val sysid: Int) : Event

    /**
     * Vehicle [sysid]'s queue: the [current] entry (null when empty), what is left of its duration
     * ([remainingS], null when unlimited) and the [pending] entries in order; with the vehicle's
     * [mode], [armed] and height above home. `pod queue status --json` prints one; `pod queue
     * serve --json` one whenever it changes (the remaining time about once a second).
     */
    @Serializable @SerialName("queue_status")
    public data class QueueStatus(
        val sysid: Int,
        val mode: String?,
        val armed: Boolean?,
        @SerialName("relative_alt_m") val relativeAltM: Finite?,
        val current: EntryJson?,
        @SerialName("remaining_s") val remainingS: Finite?,
        val pending: List<EntryJson>,
    ) : Event

    /**
     * A `pod queue` request was done; the last line. [action] is `append`, `prepend`, `replace`,
     * `replace-all`, `next` or `clear`; [entry] the entry an insertion made (its id names it in
     * the status), [ended] the entry `next` ended (null when the queue was empty); then the queue
     * after the request, as in [QueueStatus].
     */
    @Serializable @SerialName("queue_done")
    public data class QueueDone(
        val action: String,
        val sysid: Int,
        val entry: EntryJson?,
        val ended: EntryJson?,
        val current: EntryJson?,
        @SerialName("remaining_s") val remainingS: Finite?,
        val pending: List<EntryJson>,
    ) : Event

    // ---- pod demo: the program's events; [at] is vehicle time in seconds since it started ----

    /** Task [id] (child of [parent], 0 for the root) labelled [task] started with [vehicles]. */
    @Serializable @SerialName("task_started")
    public data class TaskStarted(val at: Double, val id: Int, val parent: Int, val task: String, val vehicles: List<Int>) : Event

    /** Task [id] completed. */
    @Serializable @SerialName("task_done")
    public data class TaskDone(val at: Double, val id: Int, val task: String) : Event

    /** Task [id] failed with [error]. */
    @Serializable @SerialName("task_failed")
    public data class TaskFailed(val at: Double, val id: Int, val task: String, val error: String) : Event

    /** Task [id] was cancelled (its condition fired, a deadline passed, a sibling failed, the program stopped). */
    @Serializable @SerialName("task_cancelled")
    public data class TaskCancelled(val at: Double, val id: Int, val task: String) : Event

    /** Task [task] starts flying the mission named [mission] ([steps] steps) on [vehicle]. */
    @Serializable @SerialName("flying")
    public data class Flying(val at: Double, val task: Int, val vehicle: Int, val mission: String, val steps: Int) : Event

    /**
     * What [vehicle] reported while task [task] flew it: [what] is `uploaded` (with [steps], the
     * mission's step count), `prepared` (on the ground, got ready to fly: [changes], "mode
     * STABILIZE → GUIDED", "armed"), `started`, `step_done` (with [step], the index of the step, from 0),
     * `loitering` (established on the final unlimited loiter, step [step]; the mission then runs
     * until cancelled) or `completed`.
     */
    @Serializable @SerialName("mission")
    public data class Mission(val at: Double, val task: Int, val vehicle: Int, val what: String, val step: Int?, val steps: Int?, val changes: List<String>? = null) : Event

    /** [vehicle] was put in [state] (`HOLD` or `RETURN_HOME`) after its task ended early; [confirmed] is false when it did not confirm. */
    @Serializable @SerialName("made_safe")
    public data class MadeSafe(val at: Double, val vehicle: Int, val state: String, val confirmed: Boolean) : Event

    /** The program picked [vehicles]. */
    @Serializable @SerialName("picked")
    public data class Picked(val at: Double, val vehicles: List<Int>) : Event

    /** The program released [vehicles]. */
    @Serializable @SerialName("released")
    public data class Released(val at: Double, val vehicles: List<Int>) : Event

    /** The program said [text]. */
    @Serializable @SerialName("message")
    public data class Message(val at: Double, val text: String) : Event

    /** `pod demo` ended: [ok], or [error]; [map] is the map of missions and tracks written (SVG, GeoJSON or KML). The last line. */
    @Serializable @SerialName("demo_done")
    public data class DemoDone(val ok: Boolean, val error: String?, val map: String) : Event

    /**
     * `pod survey` ended: [ok], or [error]; [photos] taken on the forward pass with [detections]
     * in all, the plan's indices of the [flagged] waypoints, the [backward] pass's measurements in
     * the order flown, and [map], the SVG written. The last line.
     */
    @Serializable @SerialName("survey_done")
    public data class SurveyDone(
        val ok: Boolean,
        val error: String?,
        val photos: Int?,
        val detections: Int?,
        val flagged: List<Int>?,
        val backward: List<Measured>?,
        val map: String,
    ) : Event

    /** One backward-pass measurement: the plan's [waypoint] and the range there in metres ([rangeM], null: none). */
    @Serializable
    public data class Measured(val waypoint: Int, @SerialName("range_m") val rangeM: Finite?)
}
