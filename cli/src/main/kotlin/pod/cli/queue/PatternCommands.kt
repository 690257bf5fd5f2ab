package pod.cli.queue

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.NullableOption
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.options.required
import com.github.ajalt.clikt.parameters.options.varargValues
import com.github.ajalt.clikt.parameters.types.double
import pod.cli.Output
import pod.cli.DURATION_FORMAT
import pod.cli.NOT_A_DURATION
import pod.cli.negativeNumbersAsArguments
import kotlin.time.Duration
import kotlin.time.DurationUnit

/**
 * `pod queue MODE PATTERN …`: builds one element from the options, checks it as the queue will
 * (the core's own checks and messages: exit 2 before anything is sent), and sends it to the host
 * to be inserted by [insertion]. Points are metres north and east of the vehicle's home.
 */
internal abstract class PatternCommand(out: Output, name: String, private val insertion: Insertion, private val summary: String) : QueueClientCommand(out, name) {
    init {
        // `--east -20`, `--radius -30` and `--points -10,5` are numbers, not unknown options.
        negativeNumbersAsArguments()
    }

    // A number is seconds, as everywhere else (pod watch --duration 30 too); units are welcome.
    private val duration by option("--duration", metavar = "DURATION", help = "how long at most ($DURATION_FORMAT; 0 or less: no limit)")
        .convert { text -> text.trim().toDoubleOrNull() ?: Duration.parseOrNull(text.trim())?.toDouble(DurationUnit.SECONDS) ?: fail(NOT_A_DURATION.format(text)) }
    private val alt by option("--alt", metavar = "A", help = "metres above home (default: the vehicle's height as the element starts)").double()

    override fun help(context: Context): String = summary

    /** The pattern the options describe. */
    protected abstract fun pattern(): PatternJson

    override fun run() {
        val element = ElementJson(pattern(), duration?.takeIf { it > 0 || it.isNaN() }, alt)
        checkedElement { element.toElement() }
        val response = ask(QueueRequest.Insert(insertion, element))
        report(insertion.command, "${insertion.done} ${response.entry?.describe() ?: element.describe()}", response)
    }

    /** An option taking a point as NORTH,EAST. */
    protected fun pointOption(name: String, help: String): NullableOption<PointJson.Local, PointJson.Local> =
        option(name, metavar = "N,E", help = help).convert { text ->
            try {
                parsePoint(text)
            } catch (e: IllegalArgumentException) {
                this.fail(e.message ?: "bad point")
            }
        }
}

/** `NORTH,EAST` in metres as a local point; throws [IllegalArgumentException] naming the text. */
internal fun parsePoint(text: String): PointJson.Local {
    val parts = text.split(',').map { it.trim().toDoubleOrNull() }
    val north = parts.getOrNull(0)
    val east = parts.getOrNull(1)
    require(parts.size == 2 && north != null && east != null) { "'$text' is not a point: give NORTH,EAST in metres from home, like 30,-10" }
    // The core's own range check (finite, within 100 km), said now rather than by the host.
    PointJson.Local(north, east).toPoint()
    return PointJson.Local(north, east)
}

private class GotoPattern(out: Output, insertion: Insertion) :
    PatternCommand(out, "goto", insertion, "Go to a point NORTH and EAST metres from home; ends there (or when --duration runs out).") {
    private val north by option("--north", metavar = "N", help = "metres north of home (negative: south)").double().required()
    private val east by option("--east", metavar = "E", help = "metres east of home (negative: west)").double().required()
    override fun pattern() = PatternJson.Goto(PointJson.Local(north, east))
}

private class CirclePattern(out: Output, insertion: Insertion) :
    PatternCommand(out, "circle", insertion, "Circle a point; never ends by itself: give --duration, or use `pod queue next`.") {
    private val north by option("--north", metavar = "N", help = "centre, metres north of home").double().required()
    private val east by option("--east", metavar = "E", help = "centre, metres east of home").double().required()
    private val radius by option("--radius", metavar = "R", help = "metres; positive turns clockwise, negative counter-clockwise").double().required()
    override fun pattern() = PatternJson.Circle(PointJson.Local(north, east), radius)
}

private class SegmentPattern(out: Output, insertion: Insertion) :
    PatternCommand(out, "segment", insertion, "Fly to one point, then along the line to another; ends there.") {
    private val from by pointOption("--from", "where the segment starts").required()
    private val to by pointOption("--to", "where it ends").required()
    override fun pattern() = PatternJson.Segment(from, to)
}

private class PathPattern(out: Output, insertion: Insertion) :
    PatternCommand(out, "path", insertion, "Fly through points in order (segments end to end); ends at the last.") {
    // Clikt ends an option's values at the first token that starts like an option ("-10,5"),
    // unless unknown options are taken as arguments; this command has none, so a mistyped option
    // is still refused (as an unexpected argument).
    override val treatUnknownOptionsAsArgs: Boolean = true

    private val points by pointOption("--points", "the points in order: N,E N,E …").varargValues(min = 1)
    override fun pattern() = PatternJson.Path(points.orEmpty())
}

private class HoldPattern(out: Output, insertion: Insertion) :
    PatternCommand(out, "hold", insertion, "Hold where the vehicle is; ends only when --duration runs out or on `pod queue next`.") {
    override fun pattern() = PatternJson.Hold
}

private class LandPattern(out: Output, insertion: Insertion) :
    PatternCommand(out, "land", insertion, "Land where the vehicle is; ends on the ground.") {
    override fun pattern() = PatternJson.Land
}

private class ReturnHomePattern(out: Output, insertion: Insertion) :
    PatternCommand(out, "return-home", insertion, "Return to launch by the autopilot's own procedure.") {
    override fun pattern() = PatternJson.ReturnHome
}

/** The patterns, as subcommands of the [insertion] command. */
internal fun patternCommands(out: Output, insertion: Insertion): List<PatternCommand> = listOf(
    GotoPattern(out, insertion), CirclePattern(out, insertion), SegmentPattern(out, insertion), PathPattern(out, insertion),
    HoldPattern(out, insertion), LandPattern(out, insertion), ReturnHomePattern(out, insertion),
)
