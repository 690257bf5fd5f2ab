package pod.launch

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.withContext
import java.util.concurrent.CopyOnWriteArrayList

/** What the first and the second signal do, without sending real ones (the process handles those: InterruptSpec). */
class InterruptionTest : StringSpec({
    val said = CopyOnWriteArrayList<String>()
    val exits = CopyOnWriteArrayList<String>()
    beforeTest {
        Interruption.reset()
        said.clear()
        exits.clear()
        Interruption.install({ said += it }, handleSignals = false)
    }
    afterSpec { Interruption.reset() }

    "the first signal cancels the running work, which finishes its clean-up; the second halts at once" {
        coroutineScope {
            val started = CompletableDeferred<Unit>()
            val cleanedUp = CompletableDeferred<Unit>()
            val work = async {
                Interruption.cancellable {
                    try {
                        started.complete(Unit)
                        awaitCancellation()
                    } finally {
                        withContext(NonCancellable) { cleanedUp.complete(Unit) }
                    }
                }
            }
            started.await()
            Interruption.onSignal("SIGINT", exit = { exits += "exit $it" }, halt = { exits += "halt $it" })
            shouldThrow<Interrupted> { work.await() }.signal shouldBe "SIGINT"
            cleanedUp.isCompleted shouldBe true
            exits shouldBe emptyList()
            said.single() shouldBe "pod: SIGINT: stopping, making the vehicles safe (press Ctrl-C again to quit at once)"
            Interruption.signal shouldBe "SIGINT"

            Interruption.onSignal("SIGINT", exit = { exits += "exit $it" }, halt = { exits += "halt $it" })
            exits shouldContainExactly listOf("halt 130")
            said.last() shouldContain "quitting now"
        }
    }

    "the signal's message says what stopping the running work does" {
        coroutineScope {
            val started = CompletableDeferred<Unit>()
            val work = async { Interruption.cancellable("closing the tlog") { started.complete(Unit); awaitCancellation() } }
            started.await()
            Interruption.onSignal("SIGINT", exit = { exits += "exit $it" }, halt = { exits += "halt $it" })
            shouldThrow<Interrupted> { work.await() }
            said.single() shouldBe "pod: SIGINT: stopping, closing the tlog (press Ctrl-C again to quit at once)"
        }
    }

    "with nothing cancellable running, the first signal ends the process" {
        Interruption.onSignal("SIGTERM", exit = { exits += "exit $it" }, halt = { exits += "halt $it" })
        exits shouldContainExactly listOf("exit 130")
        said.single() shouldContain "SIGTERM: stopped"
    }

    "work that begins after the signal is cancelled before it starts" {
        Interruption.onSignal("SIGINT", exit = { }, halt = { })
        var ran = false
        shouldThrow<Interrupted> { Interruption.cancellable { ran = true } }
        ran shouldBe false
    }

    "without a signal, cancellable only runs its block" {
        Interruption.cancellable { 42 } shouldBe 42
    }
})
