package pod.mavlink.codec

import java.lang.invoke.MethodHandle

/**
 * The wire layout of one message class and the handles that build and read its objects: computed
 * once per class by [MessagePlanner], then used for every frame.
 */
internal class MessagePlan(
    val messageClass: Class<*>,
    val id: Int,
    val crcExtra: Int,
    /** Fields in wire order: base fields by element size (largest first), then extensions. */
    val fields: Array<FieldPlan>,
    /** () -> Object: a fresh builder. */
    private val newBuilder: MethodHandle,
    /** (Object builder) -> Object: the built message. */
    private val build: MethodHandle,
) {
    /** Payload length with extension fields: what MAVLink 2 carries before truncation. */
    val length: Int = fields.sumOf { it.size }

    /** Payload length without extension fields: what MAVLink 1 carries. */
    val baseLength: Int = fields.filterNot { it.extension }.sumOf { it.size }

    /** The message in [payload]; a payload shorter than [length] is read as if zero-extended. */
    fun decode(payload: ByteArray): Any {
        val data = if (payload.size >= length) payload else payload.copyOf(length)
        val builder: Any = newBuilder.invokeExact()
        for (field in fields) {
            // The setters return the builder; the result is discarded, but its type is part of the exact call.
            @Suppress("UNUSED_VARIABLE")
            val sameBuilder: Any = field.setter.invokeExact(builder, field.read(data))
        }
        return build.invokeExact(builder)
    }

    /** The full-length payload of [message], an instance of [messageClass]. */
    fun encode(message: Any): ByteArray {
        val payload = ByteArray(length)
        for (field in fields) {
            val value: Any? = field.getter.invokeExact(message)
            field.write(payload, value)
        }
        return payload
    }
}
