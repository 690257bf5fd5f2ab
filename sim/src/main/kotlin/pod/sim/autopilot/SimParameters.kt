package pod.sim.autopilot

import pod.mavlink.param.ParamType
import kotlin.math.roundToLong

/** One parameter: name, default, type, the range the simulator accepts, and whether it can be written. */
internal data class ParamDef(
    val name: String,
    val default: Double,
    val type: ParamType = ParamType.REAL32,
    val min: Double = -Double.MAX_VALUE,
    val max: Double = Double.MAX_VALUE,
    val readOnly: Boolean = false,
)

/** Why a write was refused. */
internal enum class ParamWrite { STORED, UNKNOWN, READ_ONLY, OUT_OF_RANGE }

/**
 * A vehicle's parameter table in the order it lists it, with the wire encoding its profile names:
 * ArduPilot sends every value as a float carrying the number (a C cast, whatever the type);
 * PX4 sends integer parameters bytewise ([integersBytewise]), the int32's bits inside the float
 * field, and refuses values outside a parameter's range ([refusesOutOfRange]).
 */
internal class SimParameters(
    definitions: List<ParamDef>,
    private val integersBytewise: Boolean = false,
    private val refusesOutOfRange: Boolean = false,
) {
    private val defs: List<ParamDef> = definitions
    private val byName: Map<String, Int> = defs.withIndex().associate { (i, d) -> d.name to i }
    private val values: DoubleArray = DoubleArray(defs.size) { defs[it].default }

    /** How many parameters there are (PARAM_VALUE's param_count). */
    val count: Int get() = defs.size

    /** The parameter's position in the list, or null when there is no such parameter. */
    fun index(name: String): Int? = byName[name]

    /** The definition at [index], or null. */
    fun at(index: Int): ParamDef? = defs.getOrNull(index)

    /** The current value of [name]; throws for an unknown name (a bug in the simulator). */
    operator fun get(name: String): Double = values[byName[name] ?: error("no parameter $name")]

    /** The current value of [name], or null when the table has no such parameter. */
    fun valueOf(name: String): Double? = byName[name]?.let { values[it] }

    /**
     * Stores [value] for [name] after checking that it exists and is writable. ArduPilot stores any
     * finite number (GCS_Param.cpp, GCS_MAVLINK::handle_param_set checks only that the parameter
     * exists and may be set; AP_Param::set_float clamps integers to their type's range), so only
     * a profile with [refusesOutOfRange] (PX4) refuses a value outside the parameter's range here.
     */
    fun set(name: String, value: Double): ParamWrite {
        val i = byName[name] ?: return ParamWrite.UNKNOWN
        val def = defs[i]
        if (def.readOnly) return ParamWrite.READ_ONLY
        if (!value.isFinite()) return ParamWrite.OUT_OF_RANGE
        if (refusesOutOfRange && (value < def.min || value > def.max)) return ParamWrite.OUT_OF_RANGE
        val stored = if (def.type.isInteger) value.roundToLong().toDouble().coerceIn(def.type.range!!) else value.toFloat().toDouble()
        values[i] = stored
        return ParamWrite.STORED
    }

    /** The float that PARAM_VALUE carries for the parameter at [index]. */
    fun wireValue(index: Int): Float {
        val def = defs[index]
        val v = values[index]
        return if (integersBytewise && def.type.isInteger) Float.fromBits(v.toLong().toInt()) else v.toFloat()
    }

    /** The number a PARAM_SET's float [raw] means for the parameter at [index]. */
    fun fromWire(index: Int, raw: Float): Double {
        val def = defs[index]
        return when {
            integersBytewise && def.type.isInteger -> raw.toRawBits().toDouble()
            // ArduPilot adds 0.01 away from zero and casts, so it truncates (2.7 -> 2, 2.999 -> 3),
            // clamped to the type's range (AP_Param.cpp, AP_Param::set_float).
            def.type.isInteger -> if (raw.isFinite()) (raw + if (raw < 0) -0.01f else 0.01f).toLong().toDouble() else Double.NaN
            else -> raw.toDouble()
        }
    }
}
