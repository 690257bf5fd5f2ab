package pod.sim.fault

import kotlin.random.Random
import kotlin.time.Duration

/**
 * One datagram (or one copy of it) to hand on at time [at].
 *
 * [bytes] may be the very array that was offered when it was not corrupted; a [FaultModel] never
 * modifies what it is given, and callers should not either.
 */
public class Delivery(
    /** When to deliver it, on the same time line as the `now` given to the [FaultModel]. */
    public val at: Duration,
    /** The datagram as it should arrive. */
    public val bytes: ByteArray,
    /** Which offered datagram this is a copy of, counting from 0 in the order they were offered. */
    public val datagram: Long,
) {
    override fun equals(other: Any?): Boolean =
        other is Delivery && other.at == at && other.datagram == datagram && other.bytes.contentEquals(bytes)

    override fun hashCode(): Int = (at.hashCode() * 31 + datagram.hashCode()) * 31 + bytes.contentHashCode()

    override fun toString(): String = "Delivery(datagram=$datagram, at=$at, ${bytes.size} bytes)"
}

/**
 * The faults of one link direction as a pure, seeded machine: no sockets, no clock, no coroutines.
 * Feed it each datagram with the current time ([offer]) and, when [nextRelease] comes, call
 * [release]; both return what to deliver and when. A driver (such as [LossyRelay]) owns the
 * sockets and the timers.
 *
 * The same [faults], seed and sequence of (datagram size, time) give the same decisions (the
 * generator is `kotlin.random.Random(seed)`, which promises that only within one Kotlin version).
 * Every datagram consumes the same number of random draws whatever happens to it, so the fate of
 * datagram n depends only on the seed and n: raising [LinkFaults.drop] loses more datagrams without
 * reshuffling which ones are duplicated or corrupted, which keeps paired benchmark runs comparable.
 *
 * Not thread-safe: one caller at a time, with `now` never going backwards.
 */
public class FaultModel(
    /** What goes wrong. */
    public val faults: LinkFaults,
    seed: Long,
) {
    private val random = Random(seed)
    private val held = ArrayDeque<Held>()
    private var lastNow: Duration? = null
    private var sent = 0L
    private var dropped = 0L
    private var duplicated = 0L
    private var reordered = 0L
    private var corrupted = 0L
    private var delivered = 0L

    /** A datagram's copies waiting for later datagrams to overtake them. */
    private class Held(val copies: List<Delivery>, val releaseBy: Duration, var toOvertake: Int) {
        var overtaken = false
    }

    /** What happened so far; [LinkCounters.discarded] is always 0 here. */
    public val counters: LinkCounters
        get() = LinkCounters(sent, dropped, duplicated, reordered, corrupted, delivered)

    /** How many datagrams are held back for reordering now. */
    public val holding: Int get() = held.size

    /** When the oldest held datagram must go out even if nothing overtook it, or null when none is held. */
    public val nextRelease: Duration? get() = held.firstOrNull()?.releaseBy

    /**
     * Decides the fate of [bytes] arriving at [now]: returns the copies to deliver (none when it is
     * dropped or held back), preceded by held datagrams whose time ran out and followed by held
     * datagrams it overtook. Throws [IllegalArgumentException] if [now] is earlier than before.
     */
    public fun offer(bytes: ByteArray, now: Duration): List<Delivery> {
        advanceTo(now)
        val datagram = sent++
        // Draw everything up front, in a fixed order, whatever the outcome (see the class comment).
        val dropDraw = random.nextDouble()
        val duplicateDraw = random.nextDouble()
        val reorderDraw = random.nextDouble()
        val corruptDraw = random.nextDouble()
        val corruptPosition = random.nextDouble()
        val corruptMask = 1 + random.nextInt(255)
        val jitters = DoubleArray(2) { random.nextDouble() }

        val out = ArrayList<Delivery>(2)
        expire(now, out)
        if (dropDraw < faults.drop) {
            dropped++
            return out
        }
        var payload = bytes
        if (corruptDraw < faults.corrupt && bytes.isNotEmpty()) {
            payload = bytes.copyOf()
            val at = (corruptPosition * bytes.size).toInt().coerceAtMost(bytes.size - 1)
            payload[at] = (payload[at].toInt() xor corruptMask).toByte()
            corrupted++
        }
        val copyCount = if (duplicateDraw < faults.duplicate) 2 else 1
        duplicated += copyCount - 1
        val copies = List(copyCount) { Delivery(now + faults.delay + faults.jitter * jitters[it], payload, datagram) }

        if (reorderDraw < faults.reorder) {
            held.addLast(Held(copies, now + faults.maxHold, faults.reorderDepth))
            return out
        }
        emit(copies, out)
        overtake(copies.first().at, out)
        return out
    }

    /**
     * Releases the held datagrams whose [LinkFaults.maxHold] has run out by [now]; call it when
     * [nextRelease] comes. Throws [IllegalArgumentException] if [now] is earlier than before.
     */
    public fun release(now: Duration): List<Delivery> {
        advanceTo(now)
        val out = ArrayList<Delivery>()
        expire(now, out)
        return out
    }

    private fun advanceTo(now: Duration) {
        val last = lastNow
        require(last == null || now >= last) { "now must not go backwards: was $last, then $now" }
        lastNow = now
    }

    private fun expire(now: Duration, out: MutableList<Delivery>) {
        // Every datagram is held for the same maxHold and time only moves forward, so the deque is
        // ordered by releaseBy and only its head needs looking at.
        while (held.isNotEmpty() && held.first().releaseBy <= now) {
            val due = held.removeFirst()
            if (due.overtaken) reordered++
            emit(due.copies.map { it.notBefore(due.releaseBy) }, out)
        }
    }

    /** Counts one more datagram past every held one, releasing those that have been passed often enough. */
    private fun overtake(overtakerAt: Duration, out: MutableList<Delivery>) {
        for (waiting in held) {
            waiting.overtaken = true
            waiting.toOvertake--
        }
        // All start from the same reorderDepth, so the ones reaching 0 are always the oldest.
        while (held.isNotEmpty() && held.first().toOvertake == 0) {
            reordered++
            // Never before the datagram that overtook it, so a driver that delivers ties in list
            // order really does put it behind.
            emit(held.removeFirst().copies.map { it.notBefore(overtakerAt) }, out)
        }
    }

    private fun emit(copies: List<Delivery>, out: MutableList<Delivery>) {
        out += copies
        delivered += copies.size
    }

    private fun Delivery.notBefore(time: Duration): Delivery =
        if (at >= time) this else Delivery(time, bytes, datagram)
}
