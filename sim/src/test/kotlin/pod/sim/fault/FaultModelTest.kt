package pod.sim.fault

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.map
import io.kotest.property.checkAll
import kotlin.random.Random
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

class FaultModelTest : StringSpec({

    "with no faults every datagram comes back once, unchanged, at once and in order" {
        val model = FaultModel(LinkFaults.None, seed = 1)
        val run = drive(model, datagrams(10_000))
        run.out.map { it.datagram } shouldBe (0L until 10_000L).toList()
        run.out.forEach { it.bytes.contentEquals(run.input[it.datagram.toInt()]) shouldBe true }
        run.out.forEach { it.at shouldBe run.sentAt(it.datagram) }
        model.counters shouldBe LinkCounters(sent = 10_000, delivered = 10_000)
    }

    "drop loses the configured share of 100k datagrams" {
        for (p in listOf(0.05, 0.3, 0.9)) {
            val model = FaultModel(LinkFaults(drop = p), seed = 42)
            val run = drive(model, datagrams(100_000))
            val counters = model.counters
            (counters.dropped / 100_000.0) shouldBe (p plusOrMinus 0.01)
            counters.delivered shouldBe 100_000 - counters.dropped
            run.out.size.toLong() shouldBe counters.delivered
        }
    }

    "duplicate sends a second identical copy of the configured share" {
        val model = FaultModel(LinkFaults(duplicate = 0.2), seed = 42)
        val run = drive(model, datagrams(100_000))
        val copies = run.out.groupBy { it.datagram }
        val twice = copies.values.filter { it.size == 2 }
        (twice.size / 100_000.0) shouldBe (0.2 plusOrMinus 0.01)
        copies.values.all { it.size in 1..2 } shouldBe true
        twice.all { (first, second) -> first.bytes.contentEquals(second.bytes) } shouldBe true
        model.counters.duplicated shouldBe twice.size.toLong()
        model.counters.delivered shouldBe 100_000L + twice.size
    }

    "reorder holds a datagram back until exactly reorderDepth later ones have passed it" {
        for (depth in listOf(1, 3)) {
            val model = FaultModel(LinkFaults(reorder = 0.1, reorderDepth = depth), seed = 42)
            val run = drive(model, datagrams(100_000))
            val order = run.out.map { it.datagram }
            order.sorted() shouldBe (0L until 100_000L).toList()
            order shouldNotBe order.sorted()
            val overtakenBy = overtakers(order)
            overtakenBy.values.toSet() shouldBe setOf(0, depth)
            overtakenBy.values.count { it == depth }.toLong() shouldBe model.counters.reordered
            (model.counters.reordered / 100_000.0) shouldBe (0.1 plusOrMinus 0.01)
        }
    }

    "a held datagram goes out after maxHold when nothing follows, and is not counted as reordered" {
        val model = FaultModel(LinkFaults(reorder = 1.0, maxHold = 40.milliseconds), seed = 3)
        model.offer(byteArrayOf(1, 2, 3), 10.milliseconds).shouldBeEmpty()
        model.holding shouldBe 1
        model.nextRelease shouldBe 50.milliseconds
        model.release(49.milliseconds).shouldBeEmpty()
        model.release(60.milliseconds) shouldContainExactly listOf(Delivery(50.milliseconds, byteArrayOf(1, 2, 3), 0))
        model.nextRelease shouldBe null
        model.counters shouldBe LinkCounters(sent = 1, delivered = 1)
    }

    "delay puts every datagram between base and base + jitter after it was sent, spread evenly" {
        val model = FaultModel(LinkFaults(delay = 20.milliseconds, jitter = 30.milliseconds), seed = 42)
        val run = drive(model, datagrams(100_000))
        val latencies = run.out.map { (it.at - run.sentAt(it.datagram)).inWholeMicroseconds / 1000.0 }
        latencies.all { it >= 20.0 && it <= 50.0 } shouldBe true
        latencies.average() shouldBe (35.0 plusOrMinus 0.2)
        latencies.count { it < 27.5 } / 100_000.0 shouldBe (0.25 plusOrMinus 0.01)
    }

    "corruption changes exactly one byte of the configured share, never the caller's array" {
        val model = FaultModel(LinkFaults(corrupt = 0.25), seed = 42)
        val input = datagrams(100_000)
        val pristine = input.map { it.copyOf() }
        val run = drive(model, input)
        val changedBytes = run.out.map { d ->
            val original = pristine[d.datagram.toInt()]
            original.indices.count { original[it] != d.bytes[it] }
        }
        changedBytes.toSet() shouldBe setOf(0, 1)
        changedBytes.count { it == 1 }.toLong() shouldBe model.counters.corrupted
        (model.counters.corrupted / 100_000.0) shouldBe (0.25 plusOrMinus 0.01)
        input.indices.all { input[it].contentEquals(pristine[it]) } shouldBe true
    }

    "the same seed makes the same decisions; another seed makes others" {
        val faults = LinkFaults(
            drop = 0.1, duplicate = 0.1, reorder = 0.1, reorderDepth = 2, maxHold = 30.milliseconds,
            delay = 5.milliseconds, jitter = 10.milliseconds, corrupt = 0.1,
        )
        val first = drive(FaultModel(faults, seed = 99), datagrams(20_000)).out
        drive(FaultModel(faults, seed = 99), datagrams(20_000)).out shouldBe first
        drive(FaultModel(faults, seed = 100), datagrams(20_000)).out shouldNotBe first
    }

    "raising the drop rate only adds losses: the fate of each datagram depends on its seed and number alone" {
        val dropsAt = { p: Double ->
            val run = drive(FaultModel(LinkFaults(drop = p, duplicate = 0.1), seed = 5), datagrams(20_000))
            (0L until 20_000L).toSet() - run.out.map { it.datagram }.toSet()
        }
        dropsAt(0.3) shouldContainAll dropsAt(0.1)
    }

    "whatever the faults, every datagram is accounted for and none arrives before its base delay" {
        val probability = Arb.int(0..100).map { it / 100.0 }
        checkAll(200, probability, probability, probability, probability, Arb.int(1..4), Arb.long()) {
                drop, dup, reorder, corrupt, depth, seed ->
            val faults = LinkFaults(
                drop = drop, duplicate = dup, reorder = reorder, reorderDepth = depth, maxHold = 20.milliseconds,
                delay = 3.milliseconds, jitter = 7.milliseconds, corrupt = corrupt,
            )
            val model = FaultModel(faults, seed)
            val run = drive(model, datagrams(500, seed))
            val c = model.counters
            model.holding shouldBe 0
            c.sent - c.dropped + c.duplicated shouldBe c.delivered
            run.out.size.toLong() shouldBe c.delivered
            run.out.all { it.at >= run.sentAt(it.datagram) + faults.delay } shouldBe true
        }
    }

    "time going backwards is refused" {
        val model = FaultModel(LinkFaults.None, seed = 1)
        model.offer(byteArrayOf(1), 5.milliseconds)
        shouldThrow<IllegalArgumentException> { model.offer(byteArrayOf(2), 4.milliseconds) }.message shouldBe
            "now must not go backwards: was 5ms, then 4ms"
    }
})

/** Datagrams of 1..280 bytes (MAVLink 2's largest frame), filled from [seed]. */
private fun datagrams(count: Int, seed: Long = 0): List<ByteArray> {
    val random = Random(seed)
    return List(count) { random.nextBytes(1 + random.nextInt(280)) }
}

private class Run(val input: List<ByteArray>, val out: List<Delivery>, val step: Duration) {
    fun sentAt(datagram: Long): Duration = step * datagram.toDouble()
}

/** Offers [input] one per [step] and then lets every held datagram out. */
private fun drive(model: FaultModel, input: List<ByteArray>, step: Duration = 1.milliseconds): Run {
    val out = ArrayList<Delivery>()
    input.forEachIndexed { i, bytes -> out += model.offer(bytes, step * i) }
    out += model.release(step * input.size + 1.seconds)
    return Run(input, out, step)
}

/** For each datagram, how many higher-numbered datagrams came out before it. */
private fun overtakers(order: List<Long>): Map<Long, Int> {
    val seen = java.util.TreeSet<Long>()
    return order.associateWith { datagram -> seen.tailSet(datagram, false).size.also { seen += datagram } }
}
