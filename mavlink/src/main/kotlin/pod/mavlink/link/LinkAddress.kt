package pod.mavlink.link

/**
 * Where a MAVLink link goes, parsed from a connection string in either the MAVSDK form
 * (`udpin://0.0.0.0:14550`, `serial:///dev/ttyUSB0:57600`) or the pymavlink form
 * (`udpin:0.0.0.0:14550`, `/dev/ttyUSB0,57600`).
 */
public sealed class LinkAddress {
    /** Host name or address. */
    public abstract val host: String

    /** Port number, 0..65535 (0 binds an ephemeral port for [UdpIn]). */
    public abstract val port: Int

    /** `host:port` as a connection string writes it: an IPv6 host in brackets (`[::1]:14551`). */
    public val hostAndPort: String get() = if (':' in host) "[$host]:$port" else "$host:$port"

    /** Listen on a local UDP port; vehicles' addresses are learnt from their datagrams. */
    public data class UdpIn(override val host: String, override val port: Int) : LinkAddress() {
        override fun toString(): String = "udpin://$hostAndPort"
    }

    /** Send to a remote UDP port (and receive its replies on an ephemeral local port). */
    public data class UdpOut(override val host: String, override val port: Int) : LinkAddress() {
        override fun toString(): String = "udpout://$hostAndPort"
    }

    /** Connect to a TCP server (SITL's serial-over-TCP, a MAVLink router). */
    public data class Tcp(override val host: String, override val port: Int) : LinkAddress() {
        override fun toString(): String = "tcp://$hostAndPort"
    }

    /**
     * A tlog played back as if live ([pod.mavlink.tlog.TlogReplayLink]): it has no host ([host] is
     * empty) and no port ([port] is 0), and what is sent to it goes nowhere.
     */
    public data class Replay(
        /** The tlog's path. */
        public val path: String,
    ) : LinkAddress() {
        override val host: String get() = ""
        override val port: Int get() = 0

        override fun toString(): String = "tlog:$path"
    }

    /**
     * A serial device (a telemetry radio, a flight controller's USB port) at [baud], 8N1, no flow
     * control ([SerialLink]). It has no host ([host] is empty) and no port ([port] is 0).
     */
    public data class Serial(
        /** The device: `/dev/ttyUSB0`, `/dev/serial/by-id/…`, or `COM3` on Windows. */
        public val path: String,
        /** Bits per second, > 0. */
        public val baud: Int,
    ) : LinkAddress() {
        init {
            require(path.isNotBlank()) { "path must not be empty" }
            require(baud > 0) { "baud must be > 0, was $baud" }
        }

        override val host: String get() = ""
        override val port: Int get() = 0

        override fun toString(): String = "serial://$path:$baud"
    }

    /** Reads connection strings. */
    public companion object {
        private val FORM = Regex("""^(udpin|udpout|udp|tcp)(?::/{2}|:)(\[[^\]]+]|[^:/\[\]]*):(\d{1,5})$""")

        /**
         * Parses [text]; throws [InvalidConnectionString] naming what is wrong. `udp://` is read as
         * `udpin` (MAVSDK's meaning). Serial devices: `serial:///dev/ttyUSB0:57600` (MAVSDK: the
         * baud is required), `/dev/ttyUSB0,57600` or a bare `/dev/ttyUSB0` (pymavlink: 115200 when
         * not given), and `COM3` forms of both.
         */
        public fun parse(text: String): LinkAddress {
            SerialAddresses.parse(text)?.let { return it }
            val match = FORM.matchEntire(text.trim()) ?: throw InvalidConnectionString(
                text,
                "expected udpin://HOST:PORT, udpout://HOST:PORT, tcp://HOST:PORT or serial://DEVICE:BAUD " +
                    "(or udpin:HOST:PORT, …, DEVICE,BAUD)",
            )
            val (scheme, rawHost, rawPort) = match.destructured
            val port = rawPort.toInt()
            if (port > 65535) throw InvalidConnectionString(text, "port must be 0..65535, was $port")
            val host = rawHost.removePrefix("[").removeSuffix("]").ifEmpty { "0.0.0.0" }
            return when (scheme) {
                "udpin", "udp" -> UdpIn(host, port)
                "udpout" -> {
                    if (port == 0) throw InvalidConnectionString(text, "udpout needs a destination port, was 0")
                    UdpOut(host, port)
                }
                else -> {
                    if (port == 0) throw InvalidConnectionString(text, "tcp needs a destination port, was 0")
                    Tcp(host, port)
                }
            }
        }
    }
}
