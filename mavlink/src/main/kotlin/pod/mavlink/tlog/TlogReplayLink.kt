package pod.mavlink.tlog

import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.delay
import kotlinx.coroutines.withContext
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.update
import pod.core.time.Timebase
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.Duration.Companion.microseconds
import kotlin.time.TimeMark
import kotlin.time.TimeSource

/**
 * A tlog played back as a link: a [pod.mavlink.GroundStation] opened on it hears every recorded
 * frame at the moment it was recorded, [speed] times faster, and shows the vehicles in the log as
 * if they were live. What the station sends goes nowhere: a log cannot answer.
 *
 * Records are due at `(timestamp − first timestamp) / speed` after [receive] starts, on
 * [timebase]'s clock (a test passes a virtual one); at an infinite [speed] (`pod replay --speed
 * max`) nothing waits: the log plays as fast as the station takes it. A record stamped earlier than
 * one before it (a recorder whose clock stepped back) is delivered at once, never reordered.
 *
 * A station opened with [GroundStationConfig.timebase][pod.mavlink.GroundStationConfig.timebase]
 * = [logTimebase] lives in log time: its clock is [logClock], and its timers (silence checks, its
 * heartbeat) fire as the log passes their time, between the records they fall between, whatever
 * the speed. [receive] returns
 * when the log has been played to its end, or cut short by a [TlogTruncated] or [TlogCorrupt]
 * record, or when the link is [close]d; [progress] tells which.
 *
 * All frames arrive from one peer, [RECORDING]: a tlog keeps no source addresses.
 *
 * Opened `paused`, it plays nothing until [play]: a station's taps ([pod.mavlink.GroundStation.record])
 * and views can then be in place before the first frame, which at a high speed comes at once.
 */
public class TlogReplayLink private constructor(
    private val reader: TlogReader,
    path: Path,
    /** How many times faster than recorded the log plays: 1 is real time, infinite as fast as it can. */
    public val speed: Double,
    private val timebase: Timebase,
    paused: Boolean,
) : MavlinkLink {
    @Volatile private var closed = false
    private val paced = speed.isFinite()
    private val playing = CompletableDeferred<Unit>().apply { if (!paused) complete(Unit) }
    private var receiving = false
    private val _progress = MutableStateFlow(ReplayProgress())

    private val timeline = LogTimeline(timebase.dispatcher)

    /**
     * The log's own time as a clock: how far into the log the replay has played (the record being
     * delivered included). A station reading it ([pod.mavlink.GroundStationConfig.timebase])
     * measures a vehicle's silence in log time, at any speed and however late this process plays a
     * record: a pause of the replay is no silence of the vehicles.
     */
    public val logClock: TimeSource.WithComparableMarks = timeline.clock

    /**
     * Log time for a station on this replay: [logClock], and a dispatcher that runs coroutines on
     * the [timebase]'s dispatcher and whose `delay`s and timeouts follow [logClock], each timer
     * run as the replay passes its time, before the next record is delivered.
     */
    public val logTimebase: Timebase = Timebase(timeline.clock, timeline)

    override val address: LinkAddress = LinkAddress.Replay(path.toString())

    /** A log binds no port: 0. */
    override val localPort: Int = 0

    /** Nobody hears what is sent: a log has no peers to reach. */
    override val peers: Collection<LinkPeer> = emptyList()

    override val sendsInPlace: Boolean get() = true

    /** How far the replay has got. */
    public val progress: StateFlow<ReplayProgress> = _progress.asStateFlow()

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        synchronized(this) {
            check(!receiving) { "$address is being played already" }
            if (closed) return
            receiving = true
        }
        var first: Long? = null
        var started: TimeMark? = null
        try {
            playing.await()
            while (!closed) {
                val record = reader.next() ?: break
                val t0 = first ?: record.timestampMicros.also { first = it }
                val start = started ?: timebase.clock.markNow().also { started = it }
                val logTime = (record.timestampMicros - t0).coerceAtLeast(0).microseconds
                if (paced) {
                    val wait = logTime / speed - start.elapsedNow()
                    // On the pacing timebase: this coroutine may run on [logTimebase], whose delays wait for the log.
                    if (wait.isPositive()) withContext(timebase.dispatcher) { delay(wait) }
                    if (closed) break
                }
                timeline.advanceTo(logTime.inWholeMicroseconds)
                onBytes(RECORDING, record.frame)
                _progress.update { it.copy(records = it.records + 1, logTime = maxOf(it.logTime, logTime)) }
            }
            _progress.update { it.copy(finished = true) }
        } catch (e: TlogException) {
            // A cut or corrupt record ends the replay where it is; what came before was played.
            _progress.update { it.copy(finished = true, error = e) }
        } finally {
            reader.close()
        }
    }

    /** Starts a replay opened paused; does nothing more once it plays. */
    public fun play() {
        playing.complete(Unit)
    }

    /** Discards [bytes]: a recording cannot be talked to. */
    override suspend fun send(bytes: ByteArray, peer: LinkPeer) {}

    /** Discards [bytes], as [send]. */
    override fun sendNow(bytes: ByteArray, peer: LinkPeer) {}

    override fun close() {
        val idle = synchronized(this) {
            closed = true
            !receiving
        }
        playing.complete(Unit) // a paused replay that is closed returns from receive at once
        // A replay that never started still holds the file; one that did closes it as it returns.
        if (idle) reader.close()
    }

    /** Opens replays of tlog files. */
    public companion object {
        /** The one peer every replayed frame comes from. */
        public val RECORDING: LinkPeer = LinkPeer("tlog")

        /**
         * Opens the tlog at [path] for replay at [speed] on [timebase], playing as soon as it is
         * received from, or, if [paused], once [play] is called; at [Double.POSITIVE_INFINITY] it plays
         * unpaced. A file that cannot be opened throws [TlogException]; a [speed] that is not a number
         * > 0 throws [IllegalArgumentException].
         */
        public fun open(
            path: Path,
            speed: Double = 1.0,
            timebase: Timebase = Timebase.System,
            codec: MessageCodec = MessageCodec.Default,
            paused: Boolean = false,
        ): TlogReplayLink {
            require(speed > 0.0) { "speed must be a number > 0, was $speed" }
            return TlogReplayLink(TlogReader.open(path, codec), path, speed, timebase, paused)
        }
    }
}

/** How far a [TlogReplayLink] has played its log. */
public data class ReplayProgress(
    /** Records delivered so far. */
    public val records: Long = 0,
    /** Log time of the latest record delivered, from the first record's timestamp. */
    public val logTime: Duration = Duration.ZERO,
    /** Whether the replay has ended: the log was played to its end or up to [error]. */
    public val finished: Boolean = false,
    /** The cut or corrupt record that ended the replay early, or null. */
    public val error: TlogException? = null,
)
