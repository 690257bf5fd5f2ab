package pod.launch

import kotlinx.coroutines.CopyableThrowable
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.Job
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.job
import sun.misc.Signal
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.atomic.AtomicInteger
import kotlin.coroutines.cancellation.CancellationException
import kotlin.system.exitProcess

/**
 * Ctrl-C (SIGINT) and SIGTERM for Pod's command line, and for any app that wants a signal to make
 * its vehicles safe before the process ends.
 *
 * Left to the JVM, either signal ends the process at once and a vehicle flying a mission flies on.
 * Once [install]ed, the first signal cancels the work running inside [cancellable] (a program, a
 * vehicle command, a transfer) with [Interrupted]; that work's own clean-up makes its vehicles
 * safe, and the command says so and exits with [EXIT_CODE]. When nothing cancellable runs (a
 * script still compiling, `pod sim`, `pod watch`), the first signal ends the process. A second
 * signal ends it at once, vehicles as they are.
 *
 * Without [install] (commands run in-process by tests, scripts run by other hosts) [cancellable]
 * only runs its block.
 */
public object Interruption {
    /** The exit code of a process stopped by a signal: 128 + SIGINT's number, as shells report it. */
    public const val EXIT_CODE: Int = 130

    /** Work [cancellable] runs now, and what stopping it does, for the person at the terminal. */
    private val running = ConcurrentHashMap<Job, String>()
    private val signals = AtomicInteger()
    @Volatile private var say: (String) -> Unit = {}

    /** The signal that stopped this process ("SIGINT", "SIGTERM"), or null while none came. */
    @Volatile
    public var signal: String? = null
        private set

    /**
     * Takes over SIGINT and SIGTERM from the JVM ([handleSignals] false: only sets [say], for
     * tests); [say] tells the person at the terminal what happens.
     */
    public fun install(say: (String) -> Unit, handleSignals: Boolean = true) {
        this.say = say
        if (!handleSignals) return
        // sun.misc.Signal (jdk.unsupported) is the only way on JDK 17 to keep a signal from
        // shutting the JVM down; a shutdown hook could not wait for the vehicles to be made safe.
        for (name in listOf("INT", "TERM")) Signal.handle(Signal(name)) { onSignal("SIG$name") }
    }

    /**
     * What signal [name] does; called on the JVM's signal thread. [exit] ends the process when
     * nothing is to be made safe, [halt] on a second signal (tests pass their own).
     */
    internal fun onSignal(name: String, exit: (Int) -> Unit = { exitProcess(it) }, halt: (Int) -> Unit = { Runtime.getRuntime().halt(it) }) {
        if (signals.incrementAndGet() > 1) {
            say("pod: $name again: quitting now; vehicles are left as they are")
            halt(EXIT_CODE)
            return
        }
        signal = name
        val work = running.entries.map { it.key to it.value }
        if (work.isEmpty()) {
            say("pod: $name: stopped (nothing was flying)")
            exit(EXIT_CODE)
            return
        }
        val doing = work.map { it.second }.distinct().joinToString("; ")
        say("pod: $name: stopping, $doing (press Ctrl-C again to quit at once)")
        work.forEach { it.first.cancel(Interrupted(name)) }
    }

    /**
     * Runs [block] so that the first signal cancels it with [Interrupted]. Open the links and start
     * the vehicles' services outside [block]: they must still run while the caller makes safe.
     * [stopping] says what the caller's clean-up then does ("closing the tlog"), as the signal's
     * message tells the person at the terminal.
     */
    public suspend fun <T> cancellable(stopping: String = MAKING_SAFE, block: suspend CoroutineScope.() -> T): T = coroutineScope {
        val job = coroutineContext.job
        running[job] = stopping
        try {
            signal?.let { throw Interrupted(it) } // it came before this began
            block()
        } finally {
            running -= job
        }
    }

    /** What stopping a [cancellable] block does unless it says otherwise. */
    public const val MAKING_SAFE: String = "making the vehicles safe"

    /** Forgets every signal and running work (tests only). */
    internal fun reset() {
        signals.set(0)
        signal = null
        running.clear()
    }
}

/** The work was cancelled because the process got [signal] (SIGINT or SIGTERM). */
@OptIn(ExperimentalCoroutinesApi::class)
public class Interrupted(
    /** "SIGINT" or "SIGTERM". */
    public val signal: String,
) : CancellationException("interrupted by $signal"), CopyableThrowable<Interrupted> {
    // No copies for stack-trace recovery: a copy made from the message would lose [signal].
    override fun createCopy(): Interrupted? = null
}

/** The [Interrupted] among [error] and its causes, if any. */
public fun interruptionIn(error: Throwable?): Interrupted? =
    generateSequence(error) { it.cause }.take(10).filterIsInstance<Interrupted>().firstOrNull()
