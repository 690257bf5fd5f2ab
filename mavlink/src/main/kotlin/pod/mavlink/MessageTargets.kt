package pod.mavlink

import java.lang.reflect.Method

/** Reads the target_system field of io.dronefleet messages that have one (looked up once per class). */
internal object MessageTargets {
    private val accessors = object : ClassValue<Method?>() {
        override fun computeValue(type: Class<*>): Method? =
            runCatching { type.getMethod("targetSystem") }.getOrNull()?.takeIf { it.returnType == Int::class.javaPrimitiveType }
    }

    /** The message's target system (0 = broadcast), or null when the message has no target. */
    fun targetSystem(message: Any): Int? = accessors.get(message.javaClass)?.invoke(message) as Int?
}
