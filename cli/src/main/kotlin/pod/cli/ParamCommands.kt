package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.subcommands
import com.github.ajalt.clikt.parameters.arguments.ProcessedArgument
import com.github.ajalt.clikt.parameters.arguments.RawArgument
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.check
import com.github.ajalt.clikt.parameters.arguments.convert
import com.github.ajalt.clikt.parameters.types.double
import pod.mavlink.MavlinkVehicle
import pod.mavlink.param.ParamOutOfRange
import pod.mavlink.param.Parameter

/** `pod param`: read and write a vehicle's parameters. */
internal class ParamGroup(out: Output) : CliktCommand(name = "param") {
    init {
        subcommands(ParamGet(out), ParamSet(out))
    }

    override fun help(context: Context): String = "Read or write a vehicle's parameters (PARAM_VALUE confirms each)."

    override fun run() = Unit
}

private fun Parameter.text() = "$name = ${if (type.isInteger) value.toLong().toString() else value.toString()} (${type.name})"

/** A parameter name, refused before the link opens when MAVLink could not carry it. */
private fun RawArgument.parameterName(): ProcessedArgument<String, String> =
    convert { name -> Parameter.nameProblem(name)?.let { fail(it) } ?: name }

/** `pod param get NAME`. */
internal class ParamGet(out: Output) : VehicleCommandBase(out, "get") {
    private val name by argument(help = "parameter name, e.g. WPNAV_SPEED").parameterName()

    override fun help(context: Context): String = "Read one parameter."

    override suspend fun act(vehicle: MavlinkVehicle) {
        val p = vehicle.params.read(name)
        finish(p.text(), vehicle, action = "param-get", param = p)
    }
}

/** `pod param set NAME VALUE`. */
internal class ParamSet(out: Output) : VehicleCommandBase(out, "set") {
    init {
        negativeNumbersAsArguments()
    }

    private val name by argument(help = "parameter name").parameterName()
    private val value by argument(help = "new value (negative ones too: -1)").double().check({ "VALUE must be a finite number, was $it" }) { it.isFinite() }

    override fun help(context: Context): String = "Write one parameter and print it as the vehicle then reports it."

    override suspend fun act(vehicle: MavlinkVehicle) {
        val p = try {
            vehicle.params.write(name, value)
        } catch (e: ParamOutOfRange) {
            badInput(e.message ?: "$name: ${e.value} does not fit")
        }
        // An integer parameter stores the value rounded: say so rather than echo a number never asked for.
        val text = if (p.type.isInteger && p.value != value) {
            "$name is an integer parameter (${p.type.name}): the vehicle stored ${p.value.toLong()} for $value"
        } else {
            p.text()
        }
        finish(text, vehicle, action = "param-set", param = p, requested = value)
    }
}
