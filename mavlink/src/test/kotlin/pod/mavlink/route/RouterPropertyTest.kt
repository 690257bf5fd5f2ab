package pod.mavlink.route

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.bind
import io.kotest.property.arbitrary.boolean
import io.kotest.property.checkAll
import kotlinx.coroutines.test.runTest
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.virtualTimebase

/**
 * Random traffic through a router of three links (two listening, one `udpout`) with seven nodes
 * behind them, checked against a model of the rules written apart from the router: every frame
 * reaches each eligible endpoint exactly once, never its source, and nothing else arrives.
 */
class RouterPropertyTest : StringSpec({

    data class Op(val node: Int, val sys: Int, val comp: Int, val targeted: Boolean, val targetSys: Int, val targetComp: Int)

    val ops = Arb.list(
        Arb.bind(
            Arb.int(0..6), Arb.int(1..4), Arb.element(1, 100, 190), Arb.boolean(), Arb.int(0..5), Arb.element(0, 1, 100, 190),
        ) { node, sys, comp, targeted, ts, tc -> Op(node, sys, comp, targeted, ts, tc) },
        1..80,
    )

    "each frame reaches each eligible endpoint exactly once and never its source" {
        checkAll(PropTestConfig(seed = 27L, iterations = 150), ops) { script ->
            runTest {
                val timebase = virtualTimebase()
                val network = MemoryNetwork(backgroundScope, timebase)
                val a = network.open("udpin://127.0.0.1:14550")
                val b = network.open("udpin://127.0.0.1:14551")
                val out = network.open("udpout://127.0.0.1:14560")
                MavlinkRouter.start(listOf(a, b, out), backgroundScope, RouterConfig(timebase = timebase))
                val nodes = listOf(
                    Node.toListening("a0", network, 14550, backgroundScope),
                    Node.toListening("a1", network, 14550, backgroundScope),
                    Node.toListening("a2", network, 14550, backgroundScope),
                    Node.toListening("b0", network, 14551, backgroundScope),
                    Node.toListening("b1", network, 14551, backgroundScope),
                    Node.listening("out", network, 14560, out, backgroundScope),
                    Node.toListening("b2", network, 14551, backgroundScope),
                )
                // The model: which nodes the router knows (a udpout remote from the start) and what each was heard as.
                val known = BooleanArray(nodes.size) { nodes[it].name == "out" }
                val heard = List(nodes.size) { HashSet<Pair<Int, Int>>() }
                val expected = List(nodes.size) { ArrayList<String>() }
                script.forEachIndexed { index, op ->
                    val bytes = if (op.targeted) command(op.sys, op.comp, op.targetSys, op.targetComp, tag = index) else heartbeat(op.sys, op.comp, index.toLong())
                    known[op.node] = true
                    heard[op.node] += op.sys to op.comp
                    for (n in nodes.indices) {
                        if (n == op.node || !known[n] || (op.sys to op.comp) in heard[n]) continue
                        val eligible = when {
                            !op.targeted || op.targetSys == 0 -> true
                            op.targetComp > 0 -> (op.targetSys to op.targetComp) in heard[n]
                            else -> heard[n].any { it.first == op.targetSys }
                        }
                        if (eligible) expected[n] += bytes.hex()
                    }
                    nodes[op.node].send(bytes)
                    testScheduler.runCurrent()
                }
                for (n in nodes.indices) {
                    withClue("what ${nodes[n]} received") { nodes[n].receivedHex() shouldBe expected[n] }
                }
            }
        }
    }
})
