package pod.mavlink.codec

import io.dronefleet.mavlink.annotations.MavlinkFieldInfo
import io.dronefleet.mavlink.annotations.MavlinkMessageBuilder
import io.dronefleet.mavlink.annotations.MavlinkMessageInfo
import io.dronefleet.mavlink.util.EnumValue
import java.lang.invoke.MethodHandles
import java.lang.invoke.MethodType
import java.lang.reflect.Method
import java.lang.reflect.Modifier
import java.lang.reflect.ParameterizedType
import java.lang.reflect.Type
import java.math.BigInteger

/**
 * Derives a [MessagePlan] from an io.dronefleet message class by reading its annotations once:
 * `@MavlinkMessageInfo` for id and CRC_EXTRA, `@MavlinkFieldInfo` on the getters for the fields,
 * and the builder's annotated setters (the overload that takes exactly the getter's type; the
 * builders also offer enum-entry, vararg and collection overloads, which are not wire types).
 */
internal object MessagePlanner {
    private val lookup = MethodHandles.publicLookup()
    private val setterType = MethodType.methodType(Any::class.java, Any::class.java, Any::class.java)
    private val getterType = MethodType.methodType(Any::class.java, Any::class.java)
    private val factoryType = MethodType.methodType(Any::class.java)

    /** Wire order: base fields by element size descending (ties by declaration position), then extensions. */
    private val wireOrder = compareBy<Pair<Method, MavlinkFieldInfo>> { it.second.extension }
        .thenByDescending { if (it.second.extension) 0 else it.second.unitSize }
        .thenBy { it.second.position }

    fun plan(messageClass: Class<*>, enumTables: EnumValueTables): MessagePlan {
        val info = messageClass.getAnnotation(MavlinkMessageInfo::class.java)
            ?: throw IllegalArgumentException("${messageClass.name} is not annotated with @MavlinkMessageInfo")
        val factory = messageClass.methods.firstOrNull {
            it.isAnnotationPresent(MavlinkMessageBuilder::class.java) && Modifier.isStatic(it.modifiers) && it.parameterCount == 0
        } ?: throw IllegalArgumentException("${messageClass.name} has no @MavlinkMessageBuilder method")
        val builderClass = factory.returnType
        val setters = builderClass.methods
            .filter { it.parameterCount == 1 && it.isAnnotationPresent(MavlinkFieldInfo::class.java) }
            .groupBy { it.name }

        val getters = messageClass.methods
            .filter { it.parameterCount == 0 && it.isAnnotationPresent(MavlinkFieldInfo::class.java) }
            .map { it to it.getAnnotation(MavlinkFieldInfo::class.java) }
            .sortedWith(wireOrder)

        var offset = 0
        val fields = getters.map { (getter, fieldInfo) ->
            val setter = setters[getter.name]?.firstOrNull { it.genericParameterTypes[0] == getter.genericReturnType }
                ?: throw IllegalArgumentException(
                    "${builderClass.name} has no ${getter.name}(${getter.genericReturnType.typeName}) setter",
                )
            val kind = kindOf(getter.genericReturnType, messageClass, getter.name)
            val field = FieldPlan(
                name = getter.name,
                kind = kind,
                offset = offset,
                unitSize = fieldInfo.unitSize,
                count = maxOf(fieldInfo.arraySize, 1),
                signed = fieldInfo.signed,
                extension = fieldInfo.extension,
                enumValues = if (kind == FieldKind.ENUM) enumTables.forType(enumTypeOf(getter, fieldInfo)) else null,
                setter = lookup.unreflect(setter).asType(setterType),
                getter = lookup.unreflect(getter).asType(getterType),
            )
            offset += field.size
            field
        }
        require(offset <= FrameLayout.MAX_PAYLOAD) { "${messageClass.name} payload is $offset bytes, more than 255" }
        return MessagePlan(
            messageClass = messageClass,
            id = info.id,
            crcExtra = info.crc,
            fields = fields.toTypedArray(),
            newBuilder = lookup.unreflect(factory).asType(factoryType),
            build = lookup.unreflect(builderClass.getMethod("build")).asType(getterType),
        )
    }

    private fun kindOf(type: Type, messageClass: Class<*>, name: String): FieldKind {
        val kind = when (type) {
            Int::class.javaPrimitiveType -> FieldKind.INT
            Long::class.javaPrimitiveType -> FieldKind.LONG
            Float::class.javaPrimitiveType -> FieldKind.FLOAT
            Double::class.javaPrimitiveType -> FieldKind.DOUBLE
            BigInteger::class.java -> FieldKind.BIG_INTEGER
            String::class.java -> FieldKind.STRING
            ByteArray::class.java -> FieldKind.BYTES
            is ParameterizedType -> when (type.rawType) {
                EnumValue::class.java -> FieldKind.ENUM
                List::class.java -> when (type.actualTypeArguments[0]) {
                    Int::class.javaObjectType -> FieldKind.INT_LIST
                    Long::class.javaObjectType -> FieldKind.LONG_LIST
                    Float::class.javaObjectType -> FieldKind.FLOAT_LIST
                    Double::class.javaObjectType -> FieldKind.DOUBLE_LIST
                    else -> null
                }
                else -> null
            }
            else -> null
        }
        return kind ?: throw IllegalArgumentException("${messageClass.name}.$name has unsupported type ${type.typeName}")
    }

    private fun enumTypeOf(getter: Method, fieldInfo: MavlinkFieldInfo): Class<*> {
        val argument = (getter.genericReturnType as ParameterizedType).actualTypeArguments[0]
        return argument as? Class<*> ?: fieldInfo.enumType.java
    }
}
