package pod.sim

import pod.mavlink.link.LinkAddress
import pod.mavlink.link.MavlinkLink
import pod.mavlink.route.FanOutLink

/**
 * Opens a simulated vehicle's link to several outputs at once (`pod sim --out A --out B`), as
 * ArduPilot SITL sends to each of its `--out`s: its telemetry goes to every output and it answers
 * whoever commands it, from any of them ([FanOutLink]).
 *
 * [SimFleet] gives vehicle i the first output with its port moved by i when it listens; every other
 * listening output is moved by the same i, so each vehicle listens on ports of its own.
 */
public class FanOutOpener(
    /** The outputs, the first of which is the vehicles' [SimVehicleConfig.gcs]; at least one. */
    private val outputs: List<LinkAddress>,
    /** How each output is opened. */
    private val base: LinkOpener = LinkOpener.Udp,
) : LinkOpener {
    init {
        require(outputs.isNotEmpty()) { "outputs must not be empty" }
    }

    override suspend fun open(address: LinkAddress): MavlinkLink {
        val first = outputs.first()
        val offset = if (first is LinkAddress.UdpIn && first.port != 0 && address is LinkAddress.UdpIn) address.port - first.port else 0
        val links = ArrayList<MavlinkLink>()
        try {
            links += base.open(address)
            for (output in outputs.drop(1)) {
                links += base.open(if (output is LinkAddress.UdpIn && output.port != 0) output.copy(port = output.port + offset) else output)
            }
        } catch (e: Throwable) {
            links.forEach { it.close() }
            throw e
        }
        return links.singleOrNull() ?: FanOutLink(links)
    }
}
