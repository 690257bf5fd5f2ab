package io.kotest.provided

import io.kotest.core.config.AbstractProjectConfig
import io.kotest.engine.concurrency.SpecExecutionMode

/**
 * The end-to-end suite's kotest settings (kotest finds this class by its name).
 *
 * Most real-UDP specs spend their time waiting on simulated vehicles' clocks and on `pod` child
 * processes, not on the CPU (a sequential run keeps the two cores about a third busy), so specs run
 * [CONCURRENT_SPECS] at a time. Every spec binds ephemeral loopback ports and owns its vehicles, so
 * they do not share state; tests within a spec still run one after another.
 */
class ProjectConfig : AbstractProjectConfig() {
    override val specExecutionMode: SpecExecutionMode = SpecExecutionMode.LimitedConcurrency(CONCURRENT_SPECS)

    private companion object {
        const val CONCURRENT_SPECS = 4
    }
}
