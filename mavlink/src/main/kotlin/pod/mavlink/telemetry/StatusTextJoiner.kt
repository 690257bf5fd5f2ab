package pod.mavlink.telemetry

import pod.core.vehicle.Autopilot
import pod.core.vehicle.Severity
import pod.core.vehicle.StatusText
import pod.mavlink.firmware.Firmware

/**
 * Joins STATUSTEXT chunks into the lines the autopilot wrote. A pure machine: the caller feeds it
 * each STATUSTEXT with the time it arrived and calls [flush] now and then; no clock of its own.
 *
 * A text longer than the 50-character field is sent in chunks (MAVLink 2 extension fields): all
 * carry the same non-zero `id` and count up in `chunk_seq` from 0; a chunk whose text fills all 50
 * characters (no NUL) continues in the next, a shorter one (possibly empty) ends the line. A text
 * that fits has `id` 0. (ArduPilot libraries/GCS_MAVLink/GCS_Common.cpp, GCS::send_textv.)
 *
 * PX4 numbers differently (src/modules/mavlink/streams/STATUSTEXT.hpp, MavlinkStreamStatustext::send):
 * every text, short or long, takes the next value of a counter that starts at 0, so its first text
 * is chunked with `id` 0; and its chunks stop with the one that holds the text's end, so a text that
 * fills its chunks exactly ends on a full chunk. From PX4 ([feed]'s `sender`), `id` 0 is an id like
 * any other, and a line that so far ends on a full chunk is delivered when the next text begins
 * (PX4 sends a text's chunks back to back) or when its time is up.
 *
 * Chunks may arrive out of order or not at all over a lossy link: a line is delivered when its last
 * chunk and every one before it are in; one still incomplete [timeoutNanos] after its first chunk
 * arrived is delivered with what came (in order), so nothing the vehicle said is lost. At most
 * [maxPending] lines are kept open; a new one beyond that delivers the oldest as it is.
 */
internal class StatusTextJoiner(
    private val timeoutNanos: Long = 1_000_000_000L,
    private val maxPending: Int = 16,
) {
    private class Pending(val severity: Severity, val startedAt: Long) {
        val chunks = java.util.TreeMap<Int, String>()
        var last: Int? = null

        fun complete(): Boolean = last?.let { l -> chunks.size == l + 1 && chunks.firstKey() == 0 } ?: false

        fun text(): String = chunks.values.joinToString("")
    }

    private val pending = LinkedHashMap<Int, Pending>()

    /**
     * One STATUSTEXT: [text] as received (trailing NULs allowed), from a vehicle of [sender]; returns
     * the lines it completes.
     */
    fun feed(severity: Severity, text: String, id: Int, chunkSeq: Int, nowNanos: Long, sender: Autopilot = Autopilot.GENERIC): List<StatusText> {
        val clean = text.substringBefore('\u0000')
        val out = ArrayList<StatusText>()
        val numbersEveryText = Firmware.of(sender).numbersEveryStatusText
        if (id == 0 && !numbersEveryText) {
            out += StatusText(severity, clean)
            return out
        }
        if (numbersEveryText && chunkSeq == 0) deliverWhereWhole(except = id, out)
        // The same chunk again: the id came round (PX4's counter wraps at 65536), the old line is over.
        pending[id]?.takeIf { chunkSeq in it.chunks }?.let { old ->
            pending.remove(id)
            out += StatusText(old.severity, old.text())
        }
        val line = pending.getOrPut(id) {
            if (pending.size >= maxPending) {
                val oldest = pending.keys.first()
                pending.remove(oldest)?.let { out += StatusText(it.severity, it.text()) }
            }
            Pending(severity, nowNanos)
        }
        line.chunks[chunkSeq] = clean
        if (clean.length < FIELD_LENGTH) line.last = chunkSeq
        if (line.complete()) {
            pending.remove(id)
            out += StatusText(line.severity, line.text())
        }
        return out
    }

    /** Delivers the open lines other than [except] that hold every chunk from 0 on, the last one full. */
    private fun deliverWhereWhole(except: Int, out: MutableList<StatusText>) {
        val iterator = pending.entries.iterator()
        while (iterator.hasNext()) {
            val (id, line) = iterator.next()
            if (id != except && line.last == null && line.chunks.lastKey() == line.chunks.size - 1) {
                iterator.remove()
                out += StatusText(line.severity, line.text())
            }
        }
    }

    /** The lines still incomplete [timeoutNanos] after their first chunk, as they are. */
    fun flush(nowNanos: Long): List<StatusText> {
        if (pending.isEmpty()) return emptyList()
        val out = ArrayList<StatusText>()
        val iterator = pending.values.iterator()
        while (iterator.hasNext()) {
            val line = iterator.next()
            if (nowNanos - line.startedAt >= timeoutNanos) {
                iterator.remove()
                out += StatusText(line.severity, line.text())
            }
        }
        return out
    }

    private companion object {
        /** Characters in STATUSTEXT's text field. */
        const val FIELD_LENGTH = 50
    }
}
