package pod.core

/**
 * The root of every failure Pod reports at run time: a vehicle lost, a pick that timed out, a
 * command, mission transfer or parameter exchange the vehicle refused or never answered, a link
 * that could not open. An app catches `PodException` to handle Pod's failures without catching
 * everything else.
 *
 * Not beneath it, on purpose: argument checks of builders and constructors, which throw
 * [IllegalArgumentException] (a programming error, named with the argument and its allowed
 * range), and cancellation ([kotlinx.coroutines.CancellationException], also when a launched
 * program is interrupted by a signal), which must stay cancellation for coroutines to unwind.
 */
public open class PodException(message: String, cause: Throwable? = null) : RuntimeException(message, cause)
