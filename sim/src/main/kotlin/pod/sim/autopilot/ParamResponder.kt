package pod.sim.autopilot

import pod.core.vehicle.Severity
import pod.sim.autopilot.profile.AutopilotProfile

/**
 * The vehicle side of the parameter protocol, answering a ground station's requests from the
 * vehicle's [params] (the ground side is mavlink's `ParamService`). Reads answer with PARAM_VALUE;
 * a list request sends every parameter with its index and the count; a write answers with the
 * value now stored. An unknown name gets no answer (ArduPilot and PX4 both stay silent); a
 * read-only write (and, where the [profile] refuses them, an out-of-range one) answers with the
 * unchanged value, with the profile's line if it has one ("Param write denied" on ArduPilot).
 * ArduPilot stores out-of-range values (GCS_Param.cpp, GCS_MAVLINK::handle_param_set).
 */
internal class ParamResponder(
    private val params: SimParameters,
    private val profile: AutopilotProfile,
    private val emit: (SimOutput) -> Unit,
) {
    /** PARAM_REQUEST_READ: by [index] when it is ≥ 0, else by [id]. */
    fun read(id: String, index: Int) {
        val i = if (index >= 0) index.takeIf { it < params.count } else params.index(id)
        if (i != null) emit(SimOutput.Param(i))
    }

    /** PARAM_REQUEST_LIST. */
    fun list() {
        for (i in 0 until params.count) emit(SimOutput.Param(i))
    }

    /** PARAM_SET of [id] to the wire float [raw]. */
    fun set(id: String, raw: Float) {
        val i = params.index(id) ?: return
        val value = params.fromWire(i, raw)
        if (!value.isFinite() && profile.dropsNonFiniteWrites) return
        when (params.set(id, value)) {
            ParamWrite.READ_ONLY -> profile.readOnlyWriteText(id)?.let { emit(SimOutput.Text(Severity.WARNING, it)) }
            else -> Unit
        }
        emit(SimOutput.Param(i))
    }
}
