package pod.e2e

import java.io.File
import java.nio.file.Files
import java.util.concurrent.TimeUnit
import kotlin.system.exitProcess

/** What one `pod` command line of a [PodBatch] printed and how it exited. */
internal class PodRun(val exitCode: Int, val out: List<String>, val err: String)

/**
 * Runs several `pod` command lines one after another in one JVM of their own, each through
 * `pod.cli.run` (what `pod.cli.MainKt` calls, without ending the process), so that the JVM, the
 * scripting host and the Kotlin compiler start and warm up once for all of them instead of once
 * per command: ReadmeSpec's thirteen `pod run` compiles cost a JVM and a cold compiler each
 * before. Each command's standard output and error are told apart by a marker line that [main]
 * writes before it.
 */
internal object PodBatch {
    private const val MARK = "\u0001pod-batch"

    /**
     * Runs [runs] (each the arguments of one `pod` command) in order in one JVM, scripts cached in
     * [cache], and returns what each printed.
     */
    fun run(runs: List<List<String>>, cache: File): List<PodRun> {
        val dir = Files.createTempDirectory("pod-batch").toFile()
        try {
            val commands = File(dir, "commands")
            commands.writeText(runs.joinToString("") { args -> args.joinToString("\t", postfix = "\n") })
            val java = File(System.getProperty("java.home"), "bin/java").path
            val process = ProcessBuilder(
                java, "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"),
                "pod.e2e.PodBatchKt", commands.path,
            ).redirectOutput(File(dir, "out")).redirectError(File(dir, "err")).redirectInput(ProcessBuilder.Redirect.PIPE)
                .also { it.environment()["POD_SCRIPT_CACHE"] = cache.path }
                .start()
            process.outputStream.close()
            // A bound against a hung child, not a timing assertion.
            check(process.waitFor(10, TimeUnit.MINUTES)) { process.destroyForcibly(); "the pod batch did not finish" }
            val out = split(File(dir, "out").readLines())
            val err = split(File(dir, "err").readLines())
            check(process.exitValue() == 0 && out.size == runs.size) {
                "the pod batch ended with ${process.exitValue()} after ${out.size} of ${runs.size} commands:\n" + File(dir, "err").readText()
            }
            return out.mapIndexed { i, lines ->
                val exit = lines.last()
                check(exit.startsWith("$MARK-exit ")) { "command $i of the pod batch did not finish:\n${err.getOrNull(i).orEmpty().joinToString("\n")}" }
                PodRun(exit.removePrefix("$MARK-exit ").toInt(), lines.dropLast(1), err.getOrNull(i).orEmpty().joinToString("\n"))
            }
        } finally {
            dir.deleteRecursively()
        }
    }

    /** [lines] cut at each command's marker line (the lines before the first are dropped). */
    private fun split(lines: List<String>): List<List<String>> {
        val runs = ArrayList<MutableList<String>>()
        for (line in lines) if (line == MARK) runs += ArrayList<String>() else runs.lastOrNull()?.add(line)
        return runs
    }

    /** The child's side: each line of [commands] is one `pod` command's arguments, tab-separated. */
    fun runAll(commands: File) {
        for (line in commands.readLines()) {
            System.out.println(MARK)
            System.err.println(MARK)
            val code = pod.cli.run(line.split("\t"))
            System.out.println("$MARK-exit $code")
        }
        System.out.flush()
        System.err.flush()
    }
}

/** Entry point of a [PodBatch]'s JVM; ends it even if a command left threads behind. */
fun main(args: Array<String>) {
    PodBatch.runAll(File(args.single()))
    exitProcess(0)
}
