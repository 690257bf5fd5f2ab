package pod.mavlink.link

/**
 * Reads the serial forms of a connection string into [LinkAddress.Serial]; the rest of
 * [LinkAddress.parse] never sees them.
 *
 * What the other tools accept, and where Pod follows them:
 * - MAVSDK (`src/mavsdk/core/cli_arg.cpp`, `CliArg::parse_serial`): `serial://PATH:BAUD`, the baud
 *   required (no `:` after the path is an error), the path starting with `/` or `COM` + digits.
 *   MAVSDK splits at the first `:`; Pod splits at the last, so `/dev/serial/by-path/…0:2:1.0…`
 *   names keep their colons.
 * - pymavlink (`mavutil.py`, `mavlink_connection` and `mavserial.__init__`): any other string is
 *   a serial device, `DEVICE,BAUD` splits at the comma, and the baud defaults to 115200.
 */
internal object SerialAddresses {
    /** pymavlink's `mavlink_connection(device, baud=115200)` default. */
    const val PYMAVLINK_DEFAULT_BAUD: Int = 115_200

    /** Above any UART a MAVLink peer runs (ArduPilot's SERIALn_BAUD tops out at 2 Mbit/s). */
    private const val MAX_BAUD = 20_000_000

    private val SCHEME = Regex("""^serial(?::/{2}|:)""")
    private val COM = Regex("""^COM\d+$""", RegexOption.IGNORE_CASE)

    /**
     * The serial address [text] names, or null when it is not a serial form (another scheme);
     * throws [InvalidConnectionString] when it is one but malformed.
     */
    fun parse(text: String): LinkAddress.Serial? {
        val trimmed = text.trim()
        if (trimmed.startsWith("serial_flowcontrol:")) {
            throw InvalidConnectionString(text, "hardware flow control is not supported: use serial://DEVICE:BAUD")
        }
        val scheme = SCHEME.find(trimmed)
        return when {
            scheme != null -> mavsdkForm(text, trimmed.substring(scheme.range.last + 1))
            trimmed.startsWith("/") || COM.matches(trimmed.substringBeforeLast(',')) || trimmed.startsWith(",") ->
                pymavlinkForm(text, trimmed)
            else -> null
        }
    }

    private fun mavsdkForm(text: String, rest: String): LinkAddress.Serial {
        val colon = rest.lastIndexOf(':')
        if (colon < 0) throw InvalidConnectionString(text, "a serial link needs a baud rate after the device, as in serial:///dev/ttyUSB0:57600")
        val path = checkedPath(text, rest.substring(0, colon))
        return LinkAddress.Serial(path, baud(text, rest.substring(colon + 1)))
    }

    private fun pymavlinkForm(text: String, rest: String): LinkAddress.Serial {
        val comma = rest.lastIndexOf(',')
        if (comma < 0) {
            val afterColon = rest.substringAfterLast(':', "")
            if (afterColon.isNotEmpty() && afterColon.all { it.isDigit() }) {
                throw InvalidConnectionString(
                    text,
                    "a serial baud rate follows a comma (${rest.substringBeforeLast(':')},$afterColon) or serial:// (serial://$rest)",
                )
            }
            return LinkAddress.Serial(checkedPath(text, rest), PYMAVLINK_DEFAULT_BAUD)
        }
        return LinkAddress.Serial(checkedPath(text, rest.substring(0, comma)), baud(text, rest.substring(comma + 1)))
    }

    private fun checkedPath(text: String, path: String): String {
        if (path.isBlank()) throw InvalidConnectionString(text, "the serial device path is empty")
        if (!path.startsWith("/") && !COM.matches(path)) {
            throw InvalidConnectionString(text, "a serial device is a path starting with / (or COMn on Windows), was '$path'")
        }
        return path
    }

    private fun baud(text: String, digits: String): Int {
        if (digits.isEmpty() || !digits.all { it in '0'..'9' }) {
            throw InvalidConnectionString(text, "the baud rate must be digits, was '$digits'")
        }
        val baud = digits.trimStart('0').ifEmpty { "0" }.let { if (it.length > 9) Long.MAX_VALUE else it.toLong() }
        if (baud == 0L || baud > MAX_BAUD) throw InvalidConnectionString(text, "the baud rate must be 1..$MAX_BAUD, was $digits")
        return baud.toInt()
    }
}
