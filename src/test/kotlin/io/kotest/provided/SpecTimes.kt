package io.kotest.provided

import io.kotest.core.listeners.FinalizeSpecListener
import io.kotest.core.listeners.PrepareSpecListener
import io.kotest.core.spec.Spec
import io.kotest.core.test.TestCase
import io.kotest.engine.test.TestResult
import java.io.File
import java.lang.management.ManagementFactory
import kotlin.reflect.KClass

/**
 * Writes each spec's real start and end (seconds since the test JVM started) to
 * target/spec-times.tsv. Surefire's per-class times are wrong for kotest, which runs specs
 * concurrently and reports them as it pleases; this file says where the e2e module's minutes go
 * (sort it by its fourth column). It times, it asserts nothing.
 */
internal object SpecTimes : PrepareSpecListener, FinalizeSpecListener {
    private val file = File("target/spec-times.tsv").also { it.parentFile.mkdirs(); it.writeText("spec\tstart_s\tend_s\twall_s\n") }
    private val started = java.util.concurrent.ConcurrentHashMap<KClass<*>, Long>()

    private fun now(): Long = System.currentTimeMillis() - ManagementFactory.getRuntimeMXBean().startTime

    override suspend fun prepareSpec(kclass: KClass<out Spec>) {
        started[kclass] = now()
    }

    override suspend fun finalizeSpec(kclass: KClass<out Spec>, results: Map<TestCase, TestResult>) {
        val start = started.remove(kclass) ?: return
        val end = now()
        synchronized(this) {
            file.appendText("${kclass.simpleName}\t${"%.1f".format(start / 1000.0)}\t${"%.1f".format(end / 1000.0)}\t${"%.1f".format((end - start) / 1000.0)}\n")
        }
    }
}
