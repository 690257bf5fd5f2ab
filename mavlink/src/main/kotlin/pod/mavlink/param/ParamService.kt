package pod.mavlink.param

import io.dronefleet.mavlink.common.MavParamType
import io.dronefleet.mavlink.common.ParamRequestRead
import io.dronefleet.mavlink.common.ParamSet
import io.dronefleet.mavlink.common.ParamValue
import io.dronefleet.mavlink.util.EnumValue
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import pod.mavlink.MavlinkVehicle
import pod.mavlink.Wire
import pod.mavlink.command.CommandTiming
import pod.mavlink.firmware.Firmware
import pod.mavlink.run

/**
 * Reads and writes one vehicle's parameters (PARAM_REQUEST_READ, PARAM_SET, answered by
 * PARAM_VALUE), decoding integers the way the vehicle's autopilot encodes them.
 *
 * One exchange at a time per vehicle. Failures are [ParamTimeout], [ParamRejected] and [pod.core.vehicle.VehicleLost].
 */
public class ParamService internal constructor(
    private val vehicle: MavlinkVehicle,
    /** Attempt timeouts and the silence after which an exchange fails ([pod.mavlink.VehicleTiming.params]). */
    public val timing: CommandTiming,
) {
    private val exclusive = Mutex()
    private val types = HashMap<String, ParamType>()

    /** How this vehicle packs integers into PARAM_VALUE: by value on ArduPilot, bit for bit elsewhere. */
    public val encoding: ParamEncoding
        get() = Firmware.of(vehicle.identity.value).paramEncoding

    /** Reads parameter [name] (case-sensitive, at most 16 characters). */
    public suspend fun read(name: String): Parameter {
        checkName(name)
        return exclusive.withLock { exchange(name, null, null) }
    }

    /**
     * Writes [value] to parameter [name] and returns it as the vehicle then reports it. The
     * parameter's type is read from the vehicle first unless it is known from an earlier exchange;
     * an integer parameter is sent [value] rounded to a whole number (the returned value says so),
     * and a value its type cannot hold fails with [ParamOutOfRange] before anything is written.
     */
    public suspend fun write(name: String, value: Double): Parameter {
        checkName(name)
        require(value.isFinite()) { "value must be finite, was $value" }
        return exclusive.withLock {
            val type = synchronized(types) { types[name] } ?: exchange(name, null, null).type
            val stored = type.stored(value)
            type.range?.let { range -> if (stored !in range) throw ParamOutOfRange(name, type, value, range) }
            exchange(name, stored, type)
        }
    }

    private fun checkName(name: String) {
        Parameter.nameProblem(name)?.let { throw IllegalArgumentException(it) }
    }

    private suspend fun exchange(name: String, writing: Double?, type: ParamType?): Parameter {
        val identity = vehicle.identity.value
        val encoding = encoding
        val machine = ParamExchange(name, writing, type, timing, vehicle.roundTrips.param)
        val result = vehicle.run(
            machine,
            Wire<Parameter, Unit>(
                during = "parameter $name",
                pick = { inbound ->
                    val message = inbound.message as? ParamValue
                    if (message == null || inbound.frame.componentId != identity.componentId) null else decode(message, encoding)
                },
                encode = { request(name, writing, type, encoding, identity.systemId, identity.componentId) },
                giveUpAfter = timing.timeout,
            ),
        )
        synchronized(types) { types[name] = result.type }
        return result
    }

    private fun request(name: String, writing: Double?, type: ParamType?, encoding: ParamEncoding, system: Int, component: Int): Any =
        if (writing == null || type == null) {
            ParamRequestRead.builder().targetSystem(system).targetComponent(component).paramId(name).paramIndex(-1).build()
        } else {
            ParamSet.builder().targetSystem(system).targetComponent(component).paramId(name)
                .paramValue(encoding.encode(writing, type)).paramType(EnumValue.create<MavParamType>(type.mavValue)).build()
        }

    internal companion object {
        /** The parameter a PARAM_VALUE reports, or null when its type is not one MAVLink defines. */
        fun decode(message: ParamValue, encoding: ParamEncoding): Parameter? {
            val type = ParamType.of(message.paramType().value()) ?: return null
            return Parameter(message.paramId().trimEnd('\u0000'), encoding.decode(message.paramValue(), type), type, message.paramIndex(), message.paramCount())
        }
    }
}
