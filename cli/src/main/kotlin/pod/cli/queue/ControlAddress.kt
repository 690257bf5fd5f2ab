package pod.cli.queue

import java.net.InetAddress
import java.net.InetSocketAddress

/**
 * Where `pod queue serve` takes requests: a loopback address and a port. Only loopback is accepted
 * (127.x.x.x, ::1, localhost), so that only this machine can steer the vehicle; names are not
 * looked up (no DNS), so a name that happens to resolve to loopback is refused too.
 */
internal data class ControlAddress(val host: String, val port: Int) {
    /** The socket address, [host] being an IP literal. */
    val socketAddress: InetSocketAddress get() = InetSocketAddress(InetAddress.getByName(host), port)

    override fun toString(): String = if (':' in host) "[$host]:$port" else "$host:$port"

    companion object {
        /** 127.0.0.1 on [QueueProtocol.DEFAULT_PORT]. */
        val DEFAULT = ControlAddress("127.0.0.1", QueueProtocol.DEFAULT_PORT)

        private val IPV4 = Regex("""(\d{1,3})\.(\d{1,3})\.(\d{1,3})\.(\d{1,3})""")

        /**
         * Reads `HOST:PORT`, `[::1]:PORT` or a bare `PORT` (on 127.0.0.1); port 0 (any free one)
         * only when [anyPort]. Throws [IllegalArgumentException] with a message for people.
         */
        fun parse(text: String, anyPort: Boolean): ControlAddress {
            val (hostText, portText) = when {
                text.startsWith("[") -> text.substringAfter('[').substringBefore(']') to text.substringAfter("]", "").removePrefix(":")
                ':' !in text -> "127.0.0.1" to text
                else -> text.substringBeforeLast(':') to text.substringAfterLast(':')
            }
            val lowest = if (anyPort) 0 else 1
            val port = portText.toIntOrNull()?.takeIf { it in lowest..65535 }
                ?: throw IllegalArgumentException("'$text' has no valid port: give HOST:PORT with a port from $lowest to 65535 (the default is ${DEFAULT})")
            return ControlAddress(loopback(hostText, text), port)
        }

        /** [host] as an IP literal when it is a loopback address. */
        private fun loopback(host: String, text: String): String {
            val literal = when {
                host.equals("localhost", ignoreCase = true) -> "127.0.0.1"
                host == "::1" || host == "0:0:0:0:0:0:0:1" -> "::1"
                IPV4.matches(host) && host.split('.').all { it.toInt() <= 255 } && host.startsWith("127.") -> host
                else -> null
            }
            return literal ?: throw IllegalArgumentException(
                "the control endpoint must be on a loopback address (127.0.0.1, ::1 or localhost), so that only this machine can steer the vehicle; '$text' is not",
            )
        }
    }
}
