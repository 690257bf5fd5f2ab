package pod.mavlink.codec

import io.dronefleet.mavlink.annotations.MavlinkEntryInfo
import io.dronefleet.mavlink.annotations.MavlinkFieldInfo
import io.dronefleet.mavlink.util.EnumValue
import java.lang.reflect.Method
import java.lang.reflect.ParameterizedType
import java.lang.reflect.Type
import java.math.BigInteger
import kotlin.random.Random

/**
 * Builds io.dronefleet messages for tests by plain reflection on the message and builder classes,
 * independently of the codec's plans, so a wrong plan cannot make its own expectations.
 */
internal object TestMessages {

    /** A field as the message class declares it. */
    class Field(val name: String, val type: Type, val info: MavlinkFieldInfo) {
        val count: Int get() = maxOf(info.arraySize, 1)
    }

    fun fields(messageClass: Class<*>): List<Field> = messageClass.methods
        .filter { it.parameterCount == 0 && it.isAnnotationPresent(MavlinkFieldInfo::class.java) }
        .map { Field(it.name, it.genericReturnType, it.getAnnotation(MavlinkFieldInfo::class.java)) }

    /** A message of [messageClass] with [values] by field name; every other field gets its zero value. */
    fun build(messageClass: Class<*>, values: Map<String, Any?>): Any {
        val builder = messageClass.methods.single { it.name == "builder" && it.parameterCount == 0 }.invoke(null)
        val setters: Map<String, List<Method>> = builder.javaClass.methods
            .filter { it.parameterCount == 1 && it.isAnnotationPresent(MavlinkFieldInfo::class.java) }
            .groupBy { it.name }
        val unknown = values.keys - fields(messageClass).map { it.name }.toSet()
        require(unknown.isEmpty()) { "${messageClass.simpleName} has no fields $unknown" }
        for (field in fields(messageClass)) {
            val setter = setters.getValue(field.name).single { it.genericParameterTypes[0] == field.type }
            setter.invoke(builder, values[field.name] ?: zero(field))
        }
        return builder.javaClass.getMethod("build").invoke(builder)
    }

    /** What a field decodes to when its bytes are all zero. */
    fun zero(field: Field): Any = when (val type = field.type) {
        Int::class.javaPrimitiveType -> 0
        Long::class.javaPrimitiveType -> 0L
        Float::class.javaPrimitiveType -> 0f
        Double::class.javaPrimitiveType -> 0.0
        BigInteger::class.java -> BigInteger.ZERO
        String::class.java -> ""
        ByteArray::class.java -> ByteArray(field.count)
        is ParameterizedType -> if (type.rawType == EnumValue::class.java) {
            enumValue(field, 0)
        } else {
            List(field.count) { zeroElement(type.actualTypeArguments[0]) }
        }
        else -> error("unsupported ${type.typeName}")
    }

    private fun zeroElement(type: Type): Any = when (type) {
        Int::class.javaObjectType -> 0
        Long::class.javaObjectType -> 0L
        Float::class.javaObjectType -> 0f
        Double::class.javaObjectType -> 0.0
        else -> error("unsupported element ${type.typeName}")
    }

    @Suppress("UNCHECKED_CAST")
    fun enumValue(field: Field, value: Int): EnumValue<*> =
        EnumValue.create(enumType(field) as Class<Enum<*>>, value) // io.dronefleet's own (scanning) factory

    fun enumType(field: Field): Class<*> = (field.type as ParameterizedType).actualTypeArguments[0] as Class<*>

    /**
     * A random message of [messageClass] with every value in its wire range (no NaN, which would
     * not equal itself). About a quarter of the fields are zero so that MAVLink 2 truncation of
     * trailing zeros is exercised; with [extensions] false the extension fields are all zero.
     */
    fun random(messageClass: Class<*>, random: Random, extensions: Boolean = true): Any =
        build(
            messageClass,
            fields(messageClass).associate { field ->
                val zero = (!extensions && field.info.extension) || random.nextInt(4) == 0
                field.name to if (zero) zero(field) else randomValue(field, random)
            },
        )

    private fun randomValue(field: Field, random: Random): Any = when (val type = field.type) {
        Int::class.javaPrimitiveType -> randomInteger(field.info, random).toInt()
        Long::class.javaPrimitiveType -> randomInteger(field.info, random)
        Float::class.javaPrimitiveType -> randomFloat(random)
        Double::class.javaPrimitiveType -> randomDouble(random)
        BigInteger::class.java -> BigInteger(64, java.util.Random(random.nextLong()))
        String::class.java -> randomString(field.count, random)
        ByteArray::class.java -> random.nextBytes(field.count)
        is ParameterizedType -> if (type.rawType == EnumValue::class.java) {
            randomEnum(field, random)
        } else {
            List(field.count) {
                when (type.actualTypeArguments[0]) {
                    Int::class.javaObjectType -> randomInteger(field.info, random).toInt()
                    Long::class.javaObjectType -> randomInteger(field.info, random)
                    Float::class.javaObjectType -> randomFloat(random)
                    else -> randomDouble(random)
                }
            }
        }
        else -> error("unsupported ${type.typeName}")
    }

    /** A value of a [MavlinkFieldInfo.unitSize]-byte integer, signed or not as declared. */
    private fun randomInteger(info: MavlinkFieldInfo, random: Random): Long {
        val bits = 8 * info.unitSize
        if (bits == 64) return random.nextLong()
        val raw = random.nextLong() ushr (64 - bits)
        return if (info.signed) (raw shl (64 - bits)) shr (64 - bits) else raw
    }

    private fun randomEnum(field: Field, random: Random): EnumValue<*> {
        val declared = enumType(field).fields
            .filter { it.isEnumConstant }
            .mapNotNull { it.getAnnotation(MavlinkEntryInfo::class.java)?.value }
            .filter { field.info.unitSize >= 4 || it < (1 shl (8 * field.info.unitSize)) }
        val value = if (declared.isNotEmpty() && random.nextBoolean()) {
            declared.random(random)
        } else {
            randomInteger(field.info, random).toInt()
        }
        return enumValue(field, value)
    }

    private fun randomFloat(random: Random): Float = when (random.nextInt(8)) {
        0 -> listOf(-0f, Float.MIN_VALUE, Float.MAX_VALUE, Float.NEGATIVE_INFINITY, Float.POSITIVE_INFINITY).random(random)
        1 -> Float.fromBits(random.nextInt()).takeUnless { it.isNaN() } ?: 1f
        else -> (random.nextDouble(-1e4, 1e4)).toFloat()
    }

    private fun randomDouble(random: Random): Double = when (random.nextInt(4)) {
        0 -> Double.fromBits(random.nextLong()).takeUnless { it.isNaN() } ?: 1.0
        else -> random.nextDouble(-1e6, 1e6)
    }

    /** Printable ASCII with an occasional two-byte UTF-8 character, at most [maxBytes] bytes of UTF-8. */
    private fun randomString(maxBytes: Int, random: Random): String {
        val text = StringBuilder()
        val target = random.nextInt(maxBytes + 1)
        var bytes = 0
        while (true) {
            val c = if (random.nextInt(10) == 0) 'ü' else (0x20 + random.nextInt(0x5F)).toChar()
            val size = if (c.code < 0x80) 1 else 2
            if (bytes + size > target) return text.toString()
            text.append(c)
            bytes += size
        }
    }
}

/** Hex digits of these bytes, lower case, no separators. */
internal fun ByteArray.toHex(): String = joinToString("") { "%02x".format(it.toInt() and 0xFF) }

/** Bytes of a hex string. */
internal fun String.hexToBytes(): ByteArray = ByteArray(length / 2) { substring(2 * it, 2 * it + 2).toInt(16).toByte() }

/** Every frame [bytes] holds, through a fresh decoder fed once. */
internal fun FrameDecoder.decodeAll(bytes: ByteArray): List<MavFrame> {
    val frames = mutableListOf<MavFrame>()
    feed(bytes) { frames += it }
    return frames
}
