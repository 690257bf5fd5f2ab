package pod.sim.autopilot

import pod.core.vehicle.Severity

/**
 * The vehicle side of the parameter protocol. Reads answer with PARAM_VALUE; a list request sends
 * every parameter with its index and the count; a write answers with the value now stored. An
 * unknown name gets no answer (ArduPilot and PX4 both stay silent); a read-only write (and on PX4
 * an out-of-range one) answers with the unchanged value (ArduPilot adds "Param write denied").
 * ArduPilot stores out-of-range values (GCS_Param.cpp, GCS_MAVLINK::handle_param_set).
 */
internal class ParamService(private val ap: SimAutopilot) {
    private val params get() = ap.params

    /** PARAM_REQUEST_READ: by [index] when it is ≥ 0, else by [id]. */
    fun read(id: String, index: Int) {
        val i = if (index >= 0) index.takeIf { it < params.count } else params.index(id)
        if (i != null) ap.emit(SimOutput.Param(i))
    }

    /** PARAM_REQUEST_LIST. */
    fun list() {
        for (i in 0 until params.count) ap.emit(SimOutput.Param(i))
    }

    /** PARAM_SET of [id] to the wire float [raw]. */
    fun set(id: String, raw: Float) {
        val i = params.index(id) ?: return
        val value = params.fromWire(i, raw)
        if (!value.isFinite() && !ap.isPx4) return // ArduPilot drops NaN and infinity without a word
        when (params.set(id, value)) {
            ParamWrite.READ_ONLY -> if (!ap.isPx4) ap.text(Severity.WARNING, "Param write denied ($id)")
            else -> Unit
        }
        ap.emit(SimOutput.Param(i))
    }
}
