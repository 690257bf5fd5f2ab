package pod.core.queue

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.bind
import io.kotest.property.arbitrary.choice
import io.kotest.property.arbitrary.enum
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.map
import io.kotest.property.arbitrary.orNull
import io.kotest.property.checkAll
import pod.core.units.m
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * The queue model against a reference written the way Paparazzi's airborne code keeps its queue:
 * one array with a current index and an end index, and an element timer that counts in fixed
 * steps and resets whenever an element ends. Any sequence of insertions, `next()`, arrivals and
 * elapsed time must leave both with the same current element and the same pending list.
 */
class QueueModelPropertyTest : StringSpec({

    "any sequence of insertions, next, arrivals and elapsed time gives the reference model's current and pending elements" {
        checkAll(PropTestConfig(iterations = 2000, seed = 14), Arb.list(operation, 1..60)) { ops ->
            var model = QueueState()
            val reference = ReferenceQueue()
            var now = Duration.ZERO
            for (op in ops) {
                when (op) {
                    is Op.Insert -> {
                        val (next, entry) = model.insert(op.mode, op.element, now)
                        model = next
                        reference.insert(op.mode, entry.id, op.element.limit)
                    }
                    Op.Next -> {
                        model = model.advance(now)
                        reference.next()
                    }
                    is Op.Arrive -> {
                        // Arrival of the current element, or a late one for an element already gone.
                        val id = if (op.current) model.current?.id else op.staleId
                        if (id != null) {
                            model = model.arrived(id, now)
                            reference.arrived(id)
                        }
                    }
                    is Op.Elapse -> repeat(op.steps) {
                        now += STEP
                        model = model.expire(now)
                        reference.tick()
                    }
                    Op.Clear -> {
                        model = model.cleared()
                        reference.clear()
                    }
                }
                model.current?.id shouldBe reference.current()
                model.pending.map { it.id } shouldBe reference.pending()
                model.remaining(now) shouldBe reference.remaining()
            }
        }
    }

    "ids are never reused, whatever is removed" {
        checkAll(PropTestConfig(iterations = 300, seed = 7), Arb.list(operation, 1..80)) { ops ->
            var model = QueueState()
            val seen = mutableSetOf<Long>()
            for (op in ops) {
                if (op is Op.Insert) {
                    val (next, entry) = model.insert(op.mode, op.element, Duration.ZERO)
                    (entry.id in seen) shouldBe false
                    seen += entry.id
                    model = next
                } else if (op == Op.Clear) {
                    model = model.cleared()
                }
            }
        }
    }
}) {
    private sealed interface Op {
        data class Insert(val mode: InsertMode, val element: QueueElement) : Op
        data object Next : Op
        data class Arrive(val current: Boolean, val staleId: Long) : Op
        data class Elapse(val steps: Int) : Op
        data object Clear : Op
    }

    /**
     * Paparazzi's layout: [slots] with [currentIdx]..[endIdx) in flight order, an element timer
     * that grows by [STEP] per tick and resets when an element starts, and arrival by id. Unlike
     * Paparazzi (whose REPLACE_CURRENT on an empty queue writes a slot it never flies, and whose
     * timer does not reset on a prepend or a replacement), a new current element always starts
     * its duration afresh: those are Pod's documented semantics.
     */
    private class ReferenceQueue {
        private val slots = ArrayList<Pair<Long, Duration?>>()
        private var currentIdx = 0
        private var timer = Duration.ZERO

        fun current(): Long? = slots.getOrNull(currentIdx)?.first

        fun pending(): List<Long> = slots.drop(currentIdx + 1).map { it.first }

        fun remaining(): Duration? = slots.getOrNull(currentIdx)?.second?.let { (it - timer).coerceAtLeast(Duration.ZERO) }

        fun insert(mode: InsertMode, id: Long, duration: Duration?) {
            val empty = currentIdx >= slots.size
            when {
                empty -> {
                    slots.clear()
                    slots += id to duration
                    currentIdx = 0
                    timer = Duration.ZERO
                }
                mode == InsertMode.APPEND -> slots += id to duration
                mode == InsertMode.PREPEND -> {
                    slots.add(currentIdx, id to duration)
                    timer = Duration.ZERO
                }
                mode == InsertMode.REPLACE_CURRENT -> {
                    slots[currentIdx] = id to duration
                    timer = Duration.ZERO
                }
                else -> {
                    slots.clear()
                    slots += id to duration
                    currentIdx = 0
                    timer = Duration.ZERO
                }
            }
        }

        fun next() {
            if (currentIdx < slots.size) {
                currentIdx++
                timer = Duration.ZERO
            }
        }

        fun arrived(id: Long) {
            if (current() == id) next()
        }

        fun tick() {
            if (currentIdx >= slots.size) return
            timer += STEP
            val limit = slots[currentIdx].second
            if (limit != null && timer >= limit) next()
        }

        fun clear() {
            slots.clear()
            currentIdx = 0
            timer = Duration.ZERO
        }
    }

    private companion object {
        val STEP = 1.seconds

        val pattern: Arb<QueuePattern> = Arb.choice(
            Arb.int(-50..50).map { QueuePattern.Goto(at(it.m, (it * 2).m)) },
            Arb.int(1..40).map { QueuePattern.Circle(at(0.m, 0.m), (if (it % 2 == 0) it else -it).m) },
            Arb.int(1..5).map { n -> QueuePattern.Path(List(n) { at((it * 10).m, 0.m) }) },
            Arb.enum<InsertMode>().map { QueuePattern.Hold },
        )

        // Durations in whole steps, so that the model's exact deadline and the reference's ticks agree;
        // zero and negative durations mean none, as in Paparazzi.
        val element: Arb<QueueElement> = Arb.bind(pattern, Arb.int(-2..12).orNull(0.4)) { p, d ->
            QueueElement(p, duration = d?.seconds)
        }

        val operation: Arb<Op> = Arb.choice(
            Arb.bind(Arb.enum<InsertMode>(), element) { m, e -> Op.Insert(m, e) },
            Arb.int(0..1).map { Op.Next },
            Arb.bind(Arb.int(0..3), Arb.int(1..30)) { c, id -> Op.Arrive(c != 0, id.toLong()) },
            Arb.int(1..15).map { Op.Elapse(it) },
            Arb.int(0..9).map { if (it == 0) Op.Clear else Op.Next },
        )
    }
}
