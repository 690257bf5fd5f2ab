package pod.sim

import pod.mavlink.link.LinkAddress
import pod.mavlink.link.MavlinkLink
import pod.mavlink.link.MemoryNetwork

/**
 * How a simulated vehicle or fleet opens its links: UDP sockets or serial ports ([Udp]) or links on a
 * [MemoryNetwork] ([memory]), which run in that network's virtual time.
 */
public fun interface LinkOpener {
    /** Opens a link on [address]; throws the link's typed errors (a port in use, an unknown host). */
    public suspend fun open(address: LinkAddress): MavlinkLink

    /** The two ways Pod opens links: real sockets and serial devices, or a memory network. */
    public companion object {
        /** Real sockets and devices (UDP, TCP, serial), as [MavlinkLink.open]. */
        public val Udp: LinkOpener = LinkOpener { MavlinkLink.open(it) }

        /** Links on [network]: the same addresses, no sockets. */
        public fun memory(network: MemoryNetwork): LinkOpener = LinkOpener { network.open(it) }
    }
}
