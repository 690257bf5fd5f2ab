package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.cli.json.RouteSummary
import pod.launch.Interrupted
import pod.launch.Interruption
import pod.mavlink.link.LinkAddress
import pod.mavlink.route.MavlinkRouter
import pod.mavlink.route.RouteLinkStats
import kotlin.time.Duration.Companion.seconds

/**
 * `pod route A B [C…]`: forwards MAVLink between links as mavlink-router does ([MavlinkRouter]),
 * so `pod watch`, the vehicle commands, QGroundControl or MAVProxy share one vehicle; a line per
 * link every `--every` and when it stops.
 */
internal class RouteCommand(private val out: Output) : CliktCommand(name = "route") {
    private val connections by argument("LINK", help = "two or more links to route between (udpin:, udpout:, tcp:)").multiple(required = true)
    private val json by option("--json", help = "one JSON object per link per summary, per line").flag()
    private val every by option("--every", help = "how often to print the per-link summary ($DURATION_FORMAT)")
        .convert { it.toDurationOrNull()?.takeIf { d -> d.isPositive() } ?: fail(NOT_A_DURATION.format(it)) }.default(10.seconds)
    private val duration by option("--duration", help = "stop after this long ($DURATION_FORMAT); default: until interrupted")
        .convert { it.toDurationOrNull() ?: fail(NOT_A_DURATION.format(it)) }

    override fun help(context: Context): String =
        "Forward MAVLink between links, so several ground stations share the vehicles (as mavlink-router does)."

    override fun run() = runBlocking {
        if (connections.size < 2) badInput("pod route needs at least two links, got ${connections.size}")
        val addresses = reportingLinkErrors { connections.map(LinkAddress::parse) }
        if (addresses.distinct().size < addresses.size) badInput("the same link is given twice: ${connections.joinToString(" ")}")
        val router = reportingLinkErrors { MavlinkRouter.open(connections, this) }
        for (link in router.links) {
            out.line(
                if (json) EventJson.encode(Event.Listening(link.address.toString(), link.localPort)) else "routing ${link.address} (local port ${link.localPort})",
            )
        }
        try {
            // Ctrl-C cancels the wait below, so the final summary is printed before the process ends.
            Interruption.cancellable("printing the route summary") {
                withTimeoutOrNull(duration ?: kotlin.time.Duration.INFINITE) {
                    while (true) {
                        delay(every)
                        summary(router, final = false)
                    }
                }
            }
        } catch (e: Interrupted) {
            summary(router, final = true)
            withContext(NonCancellable) { router.closeAndAwait() }
            throw CliktError("pod: stopped by ${e.signal}", statusCode = Interruption.EXIT_CODE)
        }
        summary(router, final = true)
        withContext(NonCancellable) { router.closeAndAwait() }
    }

    private fun summary(router: MavlinkRouter, final: Boolean) {
        router.stats().zip(router.links).forEach { (s, link) -> out.line(if (json) EventJson.encode(s.event(link.localPort, final)) else s.line(final)) }
    }

    private fun RouteLinkStats.event(port: Int, final: Boolean) =
        RouteSummary(address, port, peers, received, forwarded, unrouted, badCrc, evictedPeers, sendDrops, error, final)

    private fun RouteLinkStats.line(final: Boolean): String = buildString {
        append(if (final) "route total " else "route ")
        append("$address: $peers peer${if (peers == 1) "" else "s"}, $received frames in, $forwarded forwarded out")
        if (unrouted > 0) append(", $unrouted to unknown targets dropped")
        if (badCrc > 0) append(", $badCrc bad CRC")
        if (evictedPeers > 0) append(", $evictedPeers peers evicted")
        if (sendDrops > 0) append(", $sendDrops not sent")
        error?.let { append(", link broke: $it") }
    }
}
