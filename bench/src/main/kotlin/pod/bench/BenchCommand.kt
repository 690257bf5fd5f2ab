package pod.bench

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.main
import com.github.ajalt.clikt.parameters.groups.OptionGroup
import com.github.ajalt.clikt.parameters.options.NullableOption
import com.github.ajalt.clikt.parameters.options.OptionWithValues
import com.github.ajalt.clikt.parameters.options.RawOption
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.options.split
import java.io.File
import kotlin.time.Duration

/**
 * The command line of one benchmark, read by Clikt: a subclass declares the benchmark's options
 * (`--name value`, each with its default and its allowed range) and builds its options value from
 * them in [options]. `--help` prints them; an unknown option or a value out of range ends the
 * process with Clikt's message naming the option, before anything is measured.
 */
abstract class BenchCommand<O : Any>(name: String, private val about: String) : CliktCommand(name) {
    private var parsed: O? = null

    /** The options value, from the parsed options. */
    protected abstract fun options(): O

    override fun help(context: Context): String = about

    override fun run() {
        parsed = options()
    }

    /** Reads [args]; exits the process on `--help` or a bad command line, as a benchmark's main should. */
    fun parse(args: Array<String>): O {
        main(args)
        return checkNotNull(parsed) { "$commandName: the command line was not read" }
    }
}

/** Where a benchmark writes its results besides the console; declare it with `private val report by ReportFiles()`. */
class ReportFiles : OptionGroup() {
    /** `--json FILE`: the results as JSON. */
    val json: File? by option("--json", help = "write the results as JSON here").file()

    /** `--markdown FILE`: the results as Markdown tables. */
    val markdown: File? by option("--markdown", help = "write the results as Markdown here").file()
}

/** A whole number in [range] (underscores allowed: `200_000`). */
fun RawOption.count(range: IntRange): NullableOption<Int, Int> = convert("INT") { text ->
    text.trim().replace("_", "").toIntOrNull()?.takeIf { it in range } ?: fail("must be a whole number in $range, was $text")
}

/** Comma-separated whole numbers, each in [range]: `--counts 1,10,100`. */
fun RawOption.counts(range: IntRange): OptionWithValues<List<Int>?, List<Int>, Int> = count(range).split(",")

/** A number in [range]. */
fun RawOption.number(range: ClosedFloatingPointRange<Double>): NullableOption<Double, Double> = convert("NUMBER") { text ->
    text.trim().toDoubleOrNull()?.takeIf { it in range } ?: fail("must be a number in $range, was $text")
}

/** A duration in Kotlin's notation (`20ms`, `1m`, `PT5S`) within [range]. */
fun RawOption.duration(range: ClosedRange<Duration>): NullableOption<Duration, Duration> = convert("DURATION") { text ->
    val parsed = Duration.parseOrNull(text.trim()) ?: fail("must be a duration such as 500ms or 2m, was $text")
    parsed.takeIf { it in range } ?: fail("must be in ${range.start}..${range.endInclusive}, was $parsed")
}

/** `true` or `false`, spelt out (the benchmark scripts pass `--events true`). */
fun RawOption.yesNo(): NullableOption<Boolean, Boolean> = convert("BOOL") { text ->
    text.trim().toBooleanStrictOrNull() ?: fail("must be true or false, was $text")
}

/** A file path. */
fun RawOption.file(): NullableOption<File, File> = convert("FILE") { File(it) }

/** Comma-separated names of [E]'s constants, in any case, `-` for `_`: `--conditions loopback,rtt100`. */
inline fun <reified E : Enum<E>> RawOption.names(): OptionWithValues<List<E>?, List<E>, E> = convert("NAMES") { text ->
    val name = text.trim().uppercase().replace('-', '_')
    enumValues<E>().firstOrNull { it.name == name } ?: fail("must be one of ${enumValues<E>().joinToString(",") { it.name.lowercase() }}, was $text")
}.split(",")
