package pod.mavlink.fuzz

import kotlin.random.Random

/**
 * One decoder under fuzzing. [runOne] makes one input from a seeded [Random] (the same state gives
 * the same input), runs it through the decoder, and checks the properties that must hold for any
 * input: it throws [FuzzViolation] when one fails. Any other exception it lets out is an escape:
 * the documented, typed errors of a decoder (a tlog's [pod.mavlink.tlog.TlogTruncated]) are caught
 * inside and counted in the [FuzzTally] instead. A target may keep state from one input to the next
 * (a UDP peer's decoder does), so a run is reproduced from its seed, not from one input alone.
 */
public interface FuzzTarget {
    /** A short name for reports: `datagram`, `stream`, `signed`, `tlog`. */
    public val name: String

    /** Makes, runs and checks one input, counting what it saw in [tally]. */
    public fun runOne(random: Random, tally: FuzzTally)
}

/** A property a decoder must keep for every input, broken by this one. */
public class FuzzViolation(message: String) : AssertionError(message)

/** Throws [FuzzViolation] with [message] unless [condition] holds. */
internal inline fun property(condition: Boolean, message: () -> String) {
    if (!condition) throw FuzzViolation(message())
}

/** What a fuzz run's inputs added up to; written by the one thread running the target. */
public class FuzzTally {
    /** Input bytes fed to the decoder. */
    public var bytes: Long = 0

    /** Frames (or tlog records) the decoder delivered. */
    public var frames: Long = 0

    /** Inputs refused with the decoder's documented typed error, or frames refused by a check (bad signature, replay). */
    public var refused: Long = 0

    /** Inputs of each [Mutation]. */
    public val mutations: LongArray = LongArray(Mutation.entries.size)

    /** The input being run, kept so a failure can show it. */
    public var lastInput: ByteArray = ByteArray(0)
        private set

    /** The mutation of the input being run. */
    public var lastMutation: Mutation = Mutation.NONE
        private set

    /** Records that [bytes] made by [mutation] are about to run. */
    public fun input(mutation: Mutation, bytes: ByteArray) {
        lastInput = bytes
        lastMutation = mutation
        mutations[mutation.ordinal]++
        this.bytes += bytes.size
    }
}
