package pod.mavlink.codec

import io.dronefleet.mavlink.annotations.MavlinkEntryInfo
import io.dronefleet.mavlink.util.EnumValue
import java.util.concurrent.ConcurrentHashMap

/**
 * The [EnumValue]s of one MAVLink enum type, created once per distinct wire value and then shared.
 *
 * io.dronefleet's `EnumValue.create(Class, int)` scans the enum's fields by reflection on every call;
 * decoding must not, so each value is built once (with that very call, so equality with values built
 * elsewhere holds) and cached. Values are immutable, so sharing them between messages is safe; the
 * caches tolerate races (two threads may build the same value, both results are equal).
 */
internal class EnumValueTable(private val enumType: Class<*>) {
    /** Wire values that name a declared entry; any other value gets an EnumValue without entry. */
    private val entryValues: Set<Int> = enumType.fields
        .filter { it.isEnumConstant }
        .mapNotNull { it.getAnnotation(MavlinkEntryInfo::class.java)?.value }
        .toHashSet()

    /** Byte-sized values, which nearly all enum fields carry, by direct index. */
    private val small = arrayOfNulls<EnumValue<*>>(SMALL)

    /** Larger values (bitmasks, command ids); bounded so a peer sending random bitmasks cannot grow it. */
    private val large = ConcurrentHashMap<Int, EnumValue<*>>()

    /** The EnumValue for [value], equal to `EnumValue.create(enumType, value)`. */
    fun valueOf(value: Int): EnumValue<*> {
        if (value in 0 until SMALL) {
            return small[value] ?: create(value).also { small[value] = it }
        }
        large[value]?.let { return it }
        val created = create(value)
        if (large.size < LARGE_CAP || value in entryValues) large[value] = created
        return created
    }

    @Suppress("UNCHECKED_CAST")
    private fun create(value: Int): EnumValue<*> =
        if (value in entryValues) {
            EnumValue.create(enumType as Class<Enum<*>>, value)
        } else {
            EnumValue.create<Enum<*>>(value) // no entry has this value: the scan would find nothing
        }

    private companion object {
        const val SMALL = 256
        const val LARGE_CAP = 4096
    }
}

/** One [EnumValueTable] per enum type, shared by all message plans of a codec. */
internal class EnumValueTables {
    private val tables = ConcurrentHashMap<Class<*>, EnumValueTable>()

    fun forType(enumType: Class<*>): EnumValueTable = tables.computeIfAbsent(enumType) { EnumValueTable(it) }
}
