package pod.launch

import kotlin.coroutines.Continuation
import kotlin.coroutines.cancellation.CancellationException
import kotlin.coroutines.CoroutineContext
import kotlin.coroutines.intrinsics.COROUTINE_SUSPENDED
import kotlin.coroutines.intrinsics.createCoroutineUnintercepted
import kotlin.coroutines.intrinsics.intercepted
import kotlin.coroutines.intrinsics.suspendCoroutineUninterceptedOrReturn
import kotlin.coroutines.jvm.internal.CoroutineStackFrame
import kotlin.coroutines.resume

/**
 * Where a `pod { }` program was when it failed: attached to the failure (as a suppressed
 * exception) when the failure's own stack trace cannot say, because it was thrown after the
 * program had suspended.
 *
 * A program that calls `pick { … }` or `execute(…)` suspends; when Pod later fails that call
 * (`PickTimeout`, a task's failure) the exception is made in the engine's code, and the only
 * frame of the script on its stack is the `pod {` call at the bottom. The line the program was
 * suspended at, which Kotlin's debug metadata keeps in the program's continuation, is the line a
 * person wants to see.
 */
public class ProgramLocation(
    /** The program's frame: its file and the line it was suspended at. */
    public val frame: StackTraceElement,
) :
    Throwable("the program was at ${frame.fileName}:${frame.lineNumber}", null, false, true) {
    init {
        stackTrace = arrayOf(frame)
    }

    /** Reads the program location off a failure. */
    public companion object {
        /** The location attached to [error] by a `pod { }` program's failure, if any. */
        public fun of(error: Throwable): StackTraceElement? = error.suppressed.firstNotNullOfOrNull { (it as? ProgramLocation)?.frame }
    }
}

/**
 * Runs [block] with [receiver] as `receiver.block()` does, and when it fails with an exception
 * whose stack trace holds no frame of [block]'s source file above the `pod` call, attaches a
 * [ProgramLocation] naming the line [block] was suspended at.
 */
internal suspend fun <R, T> runLocating(receiver: R, block: suspend R.() -> T): T =
    suspendCoroutineUninterceptedOrReturn { caller ->
        lateinit var program: Continuation<Unit>
        val completion = object : Continuation<T> {
            override val context: CoroutineContext get() = caller.context

            override fun resumeWith(result: Result<T>) {
                result.exceptionOrNull()?.let { note(it, program) }
                // Dispatched, not called on this stack: the block may complete before runLocating returns.
                caller.intercepted().resumeWith(result)
            }
        }
        program = block.createCoroutineUnintercepted(receiver, completion)
        program.resume(Unit)
        COROUTINE_SUSPENDED
    }

private fun note(error: Throwable, program: Continuation<Unit>) {
    if (error is CancellationException) return // a cancelled program failed nowhere in particular
    // The frame kotlin-stdlib derives from the continuation's debug metadata (file, current label's line).
    val frame = (program as? CoroutineStackFrame)?.getStackTraceElement() ?: return
    if (frame.lineNumber <= 0 || ProgramLocation.of(error) != null) return
    val abovePodCall = error.stackTrace.takeWhile { !(it.className == POD_CALL_CLASS && it.methodName.startsWith("pod")) }
    // Thrown by the program's own code (on its stack, or in a task's coroutine): its trace already says where.
    if (abovePodCall.any { it.fileName == frame.fileName }) return
    error.addSuppressed(ProgramLocation(frame))
}

private const val POD_CALL_CLASS = "pod.launch.PodKt"
