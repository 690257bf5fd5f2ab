package pod.launch

/**
 * Which fleet a program flies: the launch contract between `pod run` and the program it runs.
 *
 * `pod run` passes the choice as system properties ([FLEET_PROPERTY], [TIME_SCALE_PROPERTY]);
 * a program reads it back with [fromSystemProperties]. Run any other way (plain `kotlin x.main.kts`,
 * an IDE, a test) the properties are absent and the program gets [DEFAULT]: four simulated vehicles
 * in real time. A JVM started by hand can pass the same properties:
 * `-Dpod.fleet=connect:udpin://0.0.0.0:14550`.
 *
 * | property | values | default |
 * |---|---|---|
 * | `pod.fleet` | `sim:N` (1..254 vehicles) or `connect:ADDRESS` (a connection string as `pod watch` takes) | `sim:4` |
 * | `pod.timeScale` | vehicle seconds per real second, 0.01..1000: the simulated fleet's, or that of an external simulator run faster than real time (`pod sim --time-scale X`) | `1` |
 * | `pod.keyFile` | with `connect:`, the MAVLink 2 signing key's file ([pod.mavlink.signing.SigningKeys.fromFile]) | the key in `$POD_SIGNING_KEY`, else unsigned |
 */
public sealed interface FleetChoice {
    /** The same choice as system properties, as `pod run` sets them. */
    public fun toSystemProperties(): Map<String, String>

    /** [count] simulated vehicles on loopback, their clocks running [timeScale] times real time. */
    public data class Sim(
        /** How many vehicles, 1..254. */
        public val count: Int = 4,
        /** Simulated seconds per real second, 0.01..1000. */
        public val timeScale: Double = 1.0,
    ) : FleetChoice {
        init {
            require(count in 1..254) { "count must be in 1..254, was $count" }
            require(timeScale in 0.01..1000.0) { "timeScale must be in 0.01..1000, was $timeScale" }
        }

        override fun toSystemProperties(): Map<String, String> =
            mapOf(FLEET_PROPERTY to "sim:$count", TIME_SCALE_PROPERTY to timeScale.toString())
    }

    /**
     * Real (or externally simulated) vehicles reached through [address], e.g. `udpin://0.0.0.0:14550`,
     * whose clocks run [timeScale] times real time (1 for real vehicles; X for `pod sim --time-scale X`).
     */
    public data class Connect(
        /** The connection string, e.g. `udpin://0.0.0.0:14550`. */
        public val address: String,
        /** Vehicle seconds per real second, 0.01..1000: the program's durations count in vehicle time. */
        public val timeScale: Double = 1.0,
        /** The signing key's file; null: the key in `$POD_SIGNING_KEY`, or an unsigned link when that is unset. */
        public val keyFile: String? = null,
    ) : FleetChoice {
        init {
            require(address.isNotBlank()) { "address must not be blank" }
            require(timeScale in 0.01..1000.0) { "timeScale must be in 0.01..1000, was $timeScale" }
        }

        override fun toSystemProperties(): Map<String, String> =
            mapOf(FLEET_PROPERTY to "connect:$address") + (if (timeScale == 1.0) emptyMap() else mapOf(TIME_SCALE_PROPERTY to timeScale.toString())) +
                (if (keyFile == null) emptyMap() else mapOf(KEY_FILE_PROPERTY to keyFile))
    }

    /** The system properties a fleet choice reads. */
    public companion object {
        /** `sim:N` or `connect:ADDRESS`. */
        public const val FLEET_PROPERTY: String = "pod.fleet"

        /** Vehicle seconds per real second, for `sim:N` and `connect:ADDRESS` alike. */
        public const val TIME_SCALE_PROPERTY: String = "pod.timeScale"

        /** The signing key's file, for `connect:ADDRESS`. */
        public const val KEY_FILE_PROPERTY: String = "pod.keyFile"

        /** What a program gets when nothing chose a fleet. */
        public val DEFAULT: FleetChoice = Sim(4)

        /**
         * The choice in this JVM's system properties, or [DEFAULT] when there is none.
         * @throws IllegalArgumentException naming the property when a value is malformed.
         */
        public fun fromSystemProperties(): FleetChoice =
            parse(System.getProperty(FLEET_PROPERTY), System.getProperty(TIME_SCALE_PROPERTY), System.getProperty(KEY_FILE_PROPERTY))

        /**
         * The choice that property values [fleet], [timeScale] and [keyFile] describe (null: not set).
         * @throws IllegalArgumentException naming the property when a value is malformed.
         */
        public fun parse(fleet: String?, timeScale: String?, keyFile: String? = null): FleetChoice {
            val scale = timeScale?.let {
                it.trim().toDoubleOrNull()?.takeIf { s -> s in 0.01..1000.0 }
                    ?: throw IllegalArgumentException("$TIME_SCALE_PROPERTY must be a number in 0.01..1000, was '$it'")
            }
            val value = fleet?.trim()
            return when {
                value.isNullOrEmpty() -> if (scale == null) DEFAULT else Sim(timeScale = scale)
                value.startsWith("sim:") -> {
                    val count = value.removePrefix("sim:").toIntOrNull()?.takeIf { it in 1..254 }
                        ?: throw IllegalArgumentException("$FLEET_PROPERTY=$value: the vehicle count must be in 1..254")
                    Sim(count, scale ?: 1.0)
                }
                value.startsWith("connect:") -> {
                    val address = value.removePrefix("connect:")
                    require(address.isNotBlank()) { "$FLEET_PROPERTY=$value: the connection string is missing" }
                    Connect(address, scale ?: 1.0, keyFile?.takeIf { it.isNotBlank() })
                }
                else -> throw IllegalArgumentException("$FLEET_PROPERTY must be sim:N or connect:ADDRESS, was '$value'")
            }
        }
    }
}
