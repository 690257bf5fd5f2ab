package pod.mavlink.param

/** MAV_PARAM_TYPE: how a parameter's value is stored on the vehicle. */
public enum class ParamType(
    /** The number on the wire. */
    public val mavValue: Int,
) {
    /** 8-bit unsigned integer. */
    UINT8(1),
    /** 8-bit signed integer. */
    INT8(2),
    /** 16-bit unsigned integer. */
    UINT16(3),
    /** 16-bit signed integer. */
    INT16(4),
    /** 32-bit unsigned integer. */
    UINT32(5),
    /** 32-bit signed integer. */
    INT32(6),
    /** 64-bit unsigned integer (cannot travel in PARAM_VALUE's float). */
    UINT64(7),
    /** 64-bit signed integer (cannot travel in PARAM_VALUE's float). */
    INT64(8),
    /** 32-bit float. */
    REAL32(9),
    /** 64-bit float (cannot travel in PARAM_VALUE's float). */
    REAL64(10),
    ;

    /** True for the integer types. */
    public val isInteger: Boolean get() = this != REAL32 && this != REAL64

    /** The values the type can hold (integers), or null when any finite number fits (floats, and 64-bit integers PARAM_VALUE cannot carry). */
    public val range: ClosedFloatingPointRange<Double>?
        get() = when (this) {
            UINT8 -> 0.0..255.0
            INT8 -> -128.0..127.0
            UINT16 -> 0.0..65_535.0
            INT16 -> -32_768.0..32_767.0
            UINT32 -> 0.0..4_294_967_295.0
            INT32 -> -2_147_483_648.0..2_147_483_647.0
            else -> null
        }

    /**
     * The value to send for [value]: for an integer type the nearest whole number, half away from
     * zero. Left to the autopilot it would be truncated: ArduPilot adds 0.01 and casts
     * (AP_Param.cpp, AP_Param::set_float: 2.7 is stored as 2), and PX4's bytewise encoding
     * carries only the integer's bits.
     */
    public fun stored(value: Double): Double =
        if (isInteger) kotlin.math.sign(value) * kotlin.math.floor(kotlin.math.abs(value) + 0.5) else value.toFloat().toDouble()

    /** Reads parameter types as MAVLink numbers them (MAV_PARAM_TYPE). */
    public companion object {
        /** The type with number [value], or null for a number MAVLink does not define. */
        public fun of(value: Int): ParamType? = entries.firstOrNull { it.mavValue == value }
    }
}

/**
 * How integers travel in PARAM_VALUE's float field. ArduPilot converts the number ([CAST]: an
 * INT32 of 5 arrives as 5.0f); PX4 copies the bits ([BYTEWISE]: the float's four bytes are the
 * integer's), which is why a ground station must know whom it talks to.
 */
public enum class ParamEncoding {
    /** The float holds the numeric value (ArduPilot). */
    CAST,

    /** The float's bits are the integer's bits (PX4 and most others). */
    BYTEWISE,
    ;

    /** The value the float [wire] of [type] stands for. */
    public fun decode(wire: Float, type: ParamType): Double {
        if (this == CAST || !type.isInteger) return wire.toDouble()
        val bits = wire.toRawBits()
        return when (type) {
            ParamType.UINT8 -> (bits and 0xFF).toDouble()
            ParamType.INT8 -> bits.toByte().toDouble()
            ParamType.UINT16 -> (bits and 0xFFFF).toDouble()
            ParamType.INT16 -> bits.toShort().toDouble()
            ParamType.UINT32 -> (bits.toLong() and 0xFFFF_FFFFL).toDouble()
            else -> bits.toDouble()
        }
    }

    /** The float that carries [value] of [type]. */
    public fun encode(value: Double, type: ParamType): Float {
        if (this == CAST || !type.isInteger) return value.toFloat()
        return Float.fromBits(value.toLong().toInt())
    }
}

/** A parameter as the vehicle reported it (PARAM_VALUE). */
public data class Parameter(
    /** Its name, up to 16 characters. */
    public val name: String,
    /** Its value (integers exactly). */
    public val value: Double,
    /** How the vehicle stores it. */
    public val type: ParamType,
    /** Its position in the vehicle's list. */
    public val index: Int,
    /** How many parameters the vehicle has. */
    public val count: Int,
) {
    /** What makes a parameter name valid on the wire. */
    public companion object {
        /** The most characters a name has: PARAM_SET and PARAM_VALUE carry it in a char[16]. */
        public const val MAX_NAME_LENGTH: Int = 16

        /**
         * Why [name] cannot travel as a parameter name (empty, longer than [MAX_NAME_LENGTH], not
         * printable ASCII), or null when it can. Checked before anything is sent.
         */
        public fun nameProblem(name: String): String? = when {
            name.isEmpty() -> "a parameter name cannot be empty"
            name.length > MAX_NAME_LENGTH -> "a parameter name has at most $MAX_NAME_LENGTH characters, \"$name\" has ${name.length}"
            name.any { it !in ' '..'~' } -> "a parameter name is plain ASCII letters, digits and '_', was \"$name\""
            else -> null
        }
    }
}
