package io.kotest.provided

import io.kotest.core.extensions.SpecExecutionOrderExtension
import io.kotest.core.spec.SpecRef

/**
 * Starts the e2e specs that take longest first, the rest after them in name order. With two specs
 * at a time (see [ProjectConfig]) and name order alone, a long spec that starts late (ScriptRunSpec,
 * VehicleAnswersCliSpec, the browser specs) runs on while the other slot has nothing left to do;
 * longest first fills both slots to the end (the classic longest-processing-time rule). The list is
 * what target/spec-times.tsv ([SpecTimes]) measured, slowest first; a spec missing from it only
 * starts later, it still runs. Replaying that run's spec times in a two-slot schedule, name order
 * ends 4 % later than this one: a small gain, kept because it costs nothing.
 */
internal object LongSpecsFirst : SpecExecutionOrderExtension {
    private val slowest = listOf(
        "ReadmeSpec", "ScriptRunSpec", "VehicleAnswersCliSpec", "InterruptSpec", "ShrunkDecoderSpec", "ListingsSpec",
        "MavsdkLossyTransferSpec", "GcsQueueSpec", "AirborneSpec", "CliSpec", "GcsPlansSpec", "ReadmeWalkthroughSpec",
        "ApiDocsSpec", "GoldenTraceSpec", "SerialFlightSpec", "GcsCommandsSpec", "GcsSurveySpec", "CommonKotlinSpec",
        "GcsMapSpec", "BadInputSpec", "ReplayInteropSpec", "QueueCliSpec", "ConsumerBuildSpec",
    )

    override fun sort(specs: List<SpecRef>): List<SpecRef> =
        specs.sortedWith(compareBy<SpecRef> { rank(it) }.thenBy { it.fqn })

    private fun rank(spec: SpecRef): Int = slowest.indexOf(spec.kclass.simpleName).let { if (it < 0) slowest.size else it }
}
