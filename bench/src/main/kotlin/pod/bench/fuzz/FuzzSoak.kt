package pod.bench.fuzz

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.buildJsonObject
import kotlinx.serialization.json.put
import pod.mavlink.fuzz.DecoderFuzzTargets
import pod.mavlink.fuzz.FuzzCorpus
import pod.mavlink.fuzz.FuzzReport
import pod.mavlink.fuzz.FuzzRun
import java.util.concurrent.Callable
import java.util.concurrent.Executors
import kotlin.system.exitProcess
import kotlin.time.DurationUnit

/**
 * The decoder soak run (issue 27): every decoder of [DecoderFuzzTargets] — UDP datagrams, byte
 * streams (TCP, serial), signed frames through signature check and replay guard, tlogs — under
 * `--inputs` seeded mutated inputs (10 million by default; CI runs 100k of the same harness in
 * DecoderFuzzTest). Prints, per decoder, how long it took, inputs/s, escapes, violated properties
 * and hangs; exits 1 unless all are zero. Each run stops by itself: after its inputs, or at the
 * first input stuck for `--stuck-after`.
 *
 *     bench/fuzz.sh [--quick] [--inputs 10000000] [--decoders datagram,tlog] [--threads 2]
 */
fun main(args: Array<String>) {
    val options = FuzzSoakOptions.parse(args)
    val corpus = FuzzCorpus(seed = options.seed)
    val targets = DecoderFuzzTargets.all(corpus).filter { options.decoders.isEmpty() || it.name in options.decoders }
    if (targets.isEmpty()) {
        System.err.println("no decoder named ${options.decoders}; there are ${DecoderFuzzTargets.all(corpus).map { it.name }}")
        exitProcess(2)
    }
    println("== corpus: ${corpus.unsigned.size} unsigned and ${corpus.signed.size} signed frames (seed ${options.seed})")
    println("== ${targets.size} decoders x ${"%,d".format(options.inputs)} inputs, ${options.threads} at a time")
    val pool = Executors.newFixedThreadPool(options.threads)
    val reports = try {
        targets.map { target ->
            pool.submit(Callable { FuzzRun(target, options.seed, options.inputs, options.stuckAfter).run().also { println(it) } })
        }.map { it.get() }
    } finally {
        pool.shutdownNow()
    }
    val table = markdown(reports)
    println()
    println(table)
    options.markdown?.let { it.parentFile?.mkdirs(); it.writeText(table) }
    options.json?.let { it.parentFile?.mkdirs(); it.writeText(json(reports).toString()) }
    exitProcess(if (reports.all { it.clean }) 0 else 1)
}

private fun markdown(reports: List<FuzzReport>): String = buildString {
    appendLine("| decoder | inputs | time | inputs/s | MB fed | frames delivered | refused | escapes | violations | hangs |")
    appendLine("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for (r in reports) {
        appendLine(
            "| ${r.target} | ${"%,d".format(r.completed)} | ${"%.0f s".format(r.elapsed.toDouble(DurationUnit.SECONDS))} | " +
                "${"%,.0f".format(r.inputsPerSecond)} | ${"%.0f".format(r.bytes / 1e6)} | ${"%,d".format(r.frames)} | ${"%,d".format(r.refused)} | " +
                "${r.escapes} | ${r.violations} | ${r.hangs.size} |",
        )
    }
}

private fun json(reports: List<FuzzReport>) = JsonArray(
    reports.map { r ->
        buildJsonObject {
            put("decoder", r.target)
            put("seed", r.seed)
            put("requested", r.requested)
            put("completed", r.completed)
            put("seconds", r.elapsed.toDouble(DurationUnit.SECONDS))
            put("inputsPerSecond", r.inputsPerSecond)
            put("bytes", r.bytes)
            put("frames", r.frames)
            put("refused", r.refused)
            put("escapes", r.escapes)
            put("violations", r.violations)
            put("hangs", JsonArray(r.hangs.map { JsonPrimitive(it) }))
            put("failures", JsonArray(r.failures.map { JsonPrimitive(it.toString()) }))
            put("mutations", buildJsonObject { r.mutations.forEach { (m, n) -> put(m.name, n) } })
        }
    },
)
