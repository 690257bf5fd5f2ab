package pod.mavlink.link

import com.fazecast.jSerialComm.SerialPort
import com.fazecast.jSerialComm.SerialPortInvalidPortException
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.runInterruptible
import java.io.File
import java.io.IOException

/**
 * A serial link (a SiK telemetry radio, a flight controller's USB port) through jSerialComm: raw
 * 8N1 at the address's baud, no flow control, on the shared [StreamLink] path.
 *
 * An adapter that disappears (unplugged, power-cycled) makes a read fail (EIO on Linux) or its
 * device node vanish; the link then goes [LinkState.Down] and opens the same path again every
 * 250 ms to 1 s until the device is back. The path is resolved afresh each time, so a
 * `/dev/serial/by-id/…` link, or a pseudo-terminal pair's symlink, finds the new node.
 * pymavlink does the same only when asked (`mavlink_connection(..., autoreconnect=True)`:
 * `mavserial.reset` in mavutil.py reopens the same device after a failed write); here it is the
 * default, and reads notice the loss too, so a station that only listens sees it.
 */
internal object SerialLink {
    /** How long a read waits for bytes before checking that the device is still there. */
    private const val READ_POLL_MS = 100

    /**
     * How long one write may wait for the device to take bytes (a peer reading nothing fills the
     * buffers): what is left is dropped and counted, the caller goes on.
     */
    private const val WRITE_TIMEOUT_MS = 1000

    /**
     * Opens [address] now: a missing device throws [DeviceNotFound], one that cannot be opened
     * (permissions, held by another program) [DeviceUnavailable].
     */
    suspend fun open(address: LinkAddress.Serial): ByteStreamLink {
        val first = runInterruptible(Dispatchers.IO) { openStream(address) }
        return StreamLink(
            address, name = "serial link on ${address.path}", endedReason = "lost its device",
            first = first, remote = address, localPort = 0,
            reopening = Reopening(open = { runInterruptible(Dispatchers.IO) { openStream(address) } }),
        )
    }

    private fun openStream(address: LinkAddress.Serial): ByteStream {
        val checksPath = address.path.startsWith("/")
        if (checksPath && !File(address.path).exists()) throw DeviceNotFound(address)
        val port = try {
            SerialPort.getCommPort(address.path)
        } catch (e: SerialPortInvalidPortException) {
            throw DeviceNotFound(address, e)
        } catch (e: LinkageError) {
            throw DeviceUnavailable(address, "jSerialComm's native library did not load: ${e.message}", e)
        }
        port.setComPortParameters(address.baud, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY)
        port.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED)
        port.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING or SerialPort.TIMEOUT_WRITE_BLOCKING, READ_POLL_MS, WRITE_TIMEOUT_MS)
        if (!port.openPort()) {
            val code = port.lastErrorCode
            if (checksPath && !File(address.path).exists()) throw DeviceNotFound(address)
            throw DeviceUnavailable(address, openFailure(code))
        }
        return SerialStream(port, address.path.takeIf { checksPath })
    }

    /** The errno jSerialComm reports for a failed open, in words a user can act on. */
    private fun openFailure(errno: Int): String = when (errno) {
        EACCES -> "permission denied (on Linux, add your user to the dialout group and log in again)"
        EBUSY -> "the device is busy (another program has it open)"
        else -> "error $errno"
    }

    private const val EACCES = 13
    private const val EBUSY = 16
}

/**
 * An open jSerialComm port as a [ByteStream]. Reads block on an IO thread for at most the port's
 * read timeout at a time; between them the device node [path] (null for a `COMn` name) is checked,
 * so a device that vanished without an error on the descriptor still ends the stream.
 */
private class SerialStream(private val port: SerialPort, private val path: String?) : ByteStream {
    override suspend fun read(buffer: ByteArray): Int = runInterruptible(Dispatchers.IO) {
        var n = 0
        while (n == 0) {
            n = port.readBytes(buffer, buffer.size)
            if (n == 0 && (!port.isOpen || (path != null && !File(path).exists()))) n = -1
            // The native read does not see interrupts; a cancelled caller is noticed between polls.
            if (Thread.interrupted()) throw InterruptedException()
        }
        n
    }

    override suspend fun write(bytes: ByteArray): Int = runInterruptible(Dispatchers.IO) {
        var at = 0
        while (at < bytes.size) {
            val n = port.writeBytes(bytes, bytes.size - at, at)
            if (n < 0) throw IOException("write failed (error ${port.lastErrorCode})")
            if (n == 0) break // timed out: the rest is dropped
            at += n
        }
        at
    }

    override fun close() {
        port.closePort()
    }
}
