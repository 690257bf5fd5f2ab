package pod.core.platform

import pod.core.queue.MissionQueue
import pod.core.queue.QueueUnsupported
import pod.core.queue.WhenEmpty
import pod.core.workflow.SurveyJob
import pod.core.workflow.SurveyUnsupported

/**
 * A [Platform] that can steer a vehicle element by element through a [MissionQueue]. The engine
 * asks for it when a program flies a queue, so a platform that cannot do it has no member that
 * only throws: it simply does not implement this.
 */
public interface QueueCapable {
    /**
     * Flies [queue] on [vehicle] until it runs empty (with [whenEmpty] COMPLETE) or the caller is
     * cancelled, like [Platform.fly]: typed exceptions when the vehicle refuses or is lost, no safe
     * state of its own on cancellation.
     */
    public suspend fun flyQueue(vehicle: PlatformVehicle, queue: MissionQueue, whenEmpty: WhenEmpty)
}

/**
 * A [Platform] that can fly survey workflows ([SurveyJob]), discovered by the engine like
 * [QueueCapable].
 */
public interface SurveyCapable {
    /**
     * Flies the survey workflow [job] on [vehicle] until it is home (or, with a mission control,
     * until the operator's flight ends), like [Platform.fly]: typed exceptions, no safe state of its
     * own on cancellation.
     */
    public suspend fun flySurvey(vehicle: PlatformVehicle, job: SurveyJob<*, *>)
}

/** This platform as [QueueCapable], or [QueueUnsupported] naming it. */
internal fun Platform.queueCapable(): QueueCapable = this as? QueueCapable ?: throw QueueUnsupported(displayName())

/** This platform as [SurveyCapable], or [SurveyUnsupported] naming it. */
internal fun Platform.surveyCapable(): SurveyCapable = this as? SurveyCapable ?: throw SurveyUnsupported(displayName())

private fun Platform.displayName(): String = this::class.simpleName ?: "this platform"
