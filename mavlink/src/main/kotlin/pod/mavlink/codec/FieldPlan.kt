package pod.mavlink.codec

import io.dronefleet.mavlink.util.EnumValue
import java.lang.invoke.MethodHandle
import java.math.BigInteger
import java.util.Collections

/** How a field's wire bytes map onto the Java type that io.dronefleet's builder and getter use. */
internal enum class FieldKind {
    /** `int`: uint8, uint16, int8, int16 and int32. */
    INT,

    /** `long`: uint32 and int64. */
    LONG,

    /** `BigInteger`: uint64, decoded unsigned. */
    BIG_INTEGER,
    FLOAT,
    DOUBLE,

    /** `String`: a char array, NUL-terminated unless it fills the field, UTF-8. */
    STRING,

    /** `byte[]`: a uint8 or int8 array, copied as is. */
    BYTES,

    /** `EnumValue<E>`: an integer field typed by a MAVLink enum. */
    ENUM,
    INT_LIST,
    LONG_LIST,
    FLOAT_LIST,
    DOUBLE_LIST,
}

/**
 * One field of a message's wire layout, with the accessors that move its value between the payload
 * and io.dronefleet's objects. [setter] has type (Object builder, Object value) -> Object and
 * [getter] (Object message) -> Object, both adapted once so calls need no per-call lookup.
 */
internal class FieldPlan(
    val name: String,
    val kind: FieldKind,
    /** Byte offset in the full (zero-extended) payload. */
    val offset: Int,
    /** Size of one element in bytes. */
    val unitSize: Int,
    /** Elements: the array size, or 1 for a scalar. */
    val count: Int,
    val signed: Boolean,
    val extension: Boolean,
    /** The MAVLink enum type of an [FieldKind.ENUM] field. */
    private val enumValues: EnumValueTable?,
    val setter: MethodHandle,
    val getter: MethodHandle,
) {
    /** Bytes this field occupies on the wire. */
    val size: Int get() = unitSize * count

    /** The field's value in [payload] (at least as long as the message's full payload), boxed. */
    fun read(payload: ByteArray): Any = when (kind) {
        FieldKind.INT -> integer(payload, offset).toInt()
        FieldKind.LONG -> integer(payload, offset)
        FieldKind.BIG_INTEGER -> bigInteger(payload, offset)
        FieldKind.FLOAT -> Float.fromBits(payload.readInt32Le(offset))
        FieldKind.DOUBLE -> Double.fromBits(payload.readUnsignedLe(offset, 8))
        FieldKind.STRING -> string(payload)
        FieldKind.BYTES -> payload.copyOfRange(offset, offset + count)
        FieldKind.ENUM -> enumValue(payload)
        FieldKind.INT_LIST -> list { integer(payload, offset + it * unitSize).toInt() }
        FieldKind.LONG_LIST -> list { integer(payload, offset + it * unitSize) }
        FieldKind.FLOAT_LIST -> list { Float.fromBits(payload.readInt32Le(offset + it * unitSize)) }
        FieldKind.DOUBLE_LIST -> list { Double.fromBits(payload.readUnsignedLe(offset + it * unitSize, 8)) }
    }

    /** Writes [value] (as the getter returned it; null writes zeros) into the full-length [payload]. */
    fun write(payload: ByteArray, value: Any?) {
        if (value == null) return // the payload starts zeroed; io.dronefleet leaves unset objects null
        when (kind) {
            FieldKind.INT, FieldKind.LONG, FieldKind.FLOAT, FieldKind.DOUBLE, FieldKind.BIG_INTEGER, FieldKind.ENUM ->
                writeNumber(payload, offset, value)
            FieldKind.STRING -> {
                val bytes = (value as String).toByteArray(Charsets.UTF_8)
                // A string that fills the field has no NUL on the wire; longer ones are cut, as C and pymavlink do.
                bytes.copyInto(payload, offset, 0, minOf(bytes.size, count))
            }
            FieldKind.BYTES -> {
                val bytes = value as ByteArray
                require(bytes.size <= count) { "$name holds at most $count bytes, was ${bytes.size}" }
                bytes.copyInto(payload, offset)
            }
            FieldKind.INT_LIST, FieldKind.LONG_LIST, FieldKind.FLOAT_LIST, FieldKind.DOUBLE_LIST -> {
                val list = value as List<*>
                require(list.size <= count) { "$name holds at most $count elements, was ${list.size}" }
                list.forEachIndexed { i, element -> if (element != null) writeNumber(payload, offset + i * unitSize, element) }
            }
        }
    }

    private fun writeNumber(payload: ByteArray, at: Int, value: Any) {
        val bits = when (value) {
            is Float -> value.toRawBits().toLong()
            is Double -> value.toRawBits()
            is Number -> value.toLong() // Int, Long, BigInteger: the low unitSize bytes are the wire value
            is EnumValue<*> -> value.value().toLong()
            else -> throw IllegalArgumentException("$name: unexpected ${value.javaClass.name}")
        }
        payload.writeLe(at, unitSize, bits)
    }

    private fun integer(payload: ByteArray, at: Int): Long =
        if (signed) payload.readSignedLe(at, unitSize) else payload.readUnsignedLe(at, unitSize)

    private fun bigInteger(payload: ByteArray, at: Int): BigInteger {
        val raw = integer(payload, at)
        // io.dronefleet reads uint64 as a signed BigInteger; the wire type is unsigned, so values ≥ 2^63 stay positive.
        return if (raw >= 0 || signed) BigInteger.valueOf(raw) else BigInteger.valueOf(raw).add(TWO_TO_64)
    }

    private fun enumValue(payload: ByteArray): EnumValue<*> {
        val table = enumValues ?: error("$name has no enum type")
        return table.valueOf(integer(payload, offset).toInt())
    }

    private fun string(payload: ByteArray): String {
        var end = offset
        val limit = offset + count
        while (end < limit && payload[end].toInt() != 0) end++
        return String(payload, offset, end - offset, Charsets.UTF_8)
    }

    private inline fun list(element: (Int) -> Any): List<Any> {
        val values = arrayOfNulls<Any>(count)
        for (i in 0 until count) values[i] = element(i)
        @Suppress("UNCHECKED_CAST")
        return Collections.unmodifiableList(values.asList() as List<Any>)
    }

    private companion object {
        val TWO_TO_64: BigInteger = BigInteger.ONE.shiftLeft(64)
    }
}
