package pod.test

import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import pod.sim.fault.LinkFaults
import kotlin.time.Duration
import kotlin.time.Duration.Companion.microseconds
import kotlin.time.Duration.Companion.milliseconds

/**
 * Link fault models within [max]: each probability drawn from 0 up to [max]'s, the delay and
 * jitter from zero up to [max]'s, the reorder depth from 1 up to [max]'s, [max]'s hold limit.
 * The default bound is a bad radio link: up to 30 % lost, a few percent duplicated and reordered,
 * 1 % corrupted, up to 20 ms late with 10 ms of jitter.
 */
public fun Arb.Companion.linkFaults(
    max: LinkFaults = LinkFaults(drop = 0.3, duplicate = 0.05, reorder = 0.05, corrupt = 0.01, delay = 20.milliseconds, jitter = 10.milliseconds),
): Arb<LinkFaults> = arbitrary { rs ->
    val random = rs.random
    fun share(bound: Double) = random.within(0.0..bound)
    fun late(bound: Duration) = if (bound == Duration.ZERO) Duration.ZERO else random.nextLong(0, bound.inWholeMicroseconds + 1).microseconds
    LinkFaults(
        drop = share(max.drop),
        duplicate = share(max.duplicate),
        reorder = share(max.reorder),
        reorderDepth = random.nextInt(1, max.reorderDepth + 1),
        maxHold = max.maxHold,
        delay = late(max.delay),
        jitter = late(max.jitter),
        corrupt = share(max.corrupt),
    )
}
