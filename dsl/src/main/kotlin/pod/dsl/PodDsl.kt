package pod.dsl

/** Marks Pod's DSL receivers so that an inner block cannot silently call an outer builder. */
@DslMarker
public annotation class PodDsl
