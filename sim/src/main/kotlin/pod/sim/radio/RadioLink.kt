package pod.sim.radio

import io.dronefleet.mavlink.common.RadioStatus
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import pod.core.time.Timebase
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import kotlin.random.Random

/**
 * A simulated vehicle's [link][inner] seen through an emulated SiK radio pair ([radio]): what the
 * ground station sends waits in the ground radio's bounded buffer and reaches the vehicle at the
 * serial rate (bytes beyond the buffer are lost and counted in [uplinkDropped]); what the vehicle
 * sends crosses the same way through the vehicle radio's buffer; and each ground-station HEARTBEAT
 * that crosses makes the ground radio report RADIO_STATUS back to the station, with `txbuf` read
 * from its buffer. See [SikRadio] for the firmware facts modelled.
 *
 * Time is [timebase]'s: on a [pod.mavlink.link.MemoryNetwork] under a test scheduler the radio
 * runs in virtual time (deterministic for a [SikRadio.seed]); on UDP sockets, in real time. Its
 * coroutines run inside [receive], so they live and end with the vehicle's receive loop.
 */
public class RadioLink(
    private val inner: MavlinkLink,
    /** The radio pair emulated: its serial rate, buffer size and the link quality it reports. */
    public val radio: SikRadio,
    timebase: Timebase = Timebase.System,
) : MavlinkLink {
    private val uplink = SerialBuffer(radio.bufferBytes, radio.bytesPerSecond, timebase.clock)
    private val downlink = SerialBuffer(radio.bufferBytes, radio.bytesPerSecond, timebase.clock)
    private val encoder = FrameEncoder()
    private val random = Random(radio.seed)
    private var reportSequence = 0

    /** Bytes from the ground station the ground radio dropped, its buffer full. */
    public val uplinkDropped: Long get() = uplink.dropped

    /** Bytes from the ground station that reached the vehicle. */
    public val uplinkCarried: Long get() = uplink.carried

    /** Bytes from the vehicle its radio dropped, its buffer full. */
    public val downlinkDropped: Long get() = downlink.dropped

    /** Bytes from the vehicle that reached the ground station. */
    public val downlinkCarried: Long get() = downlink.carried

    /** RADIO_STATUS reports the ground radio sent. */
    @Volatile public var reports: Long = 0
        private set

    override val address: LinkAddress get() = inner.address
    override val localPort: Int get() = inner.localPort
    override val peers: Collection<LinkPeer> get() = inner.peers

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit): Unit = coroutineScope {
        val carrying = listOf(
            launch {
                uplink.drain { peer, bytes ->
                    onBytes(peer, bytes)
                    if (isHeartbeat(bytes)) report(peer)
                }
            },
            launch { downlink.drain { peer, bytes -> inner.send(bytes, peer) } },
        )
        try {
            inner.receive { peer, bytes -> uplink.offer(peer, bytes) }
        } finally {
            carrying.forEach { it.cancel() }
        }
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) {
        downlink.offer(peer, bytes)
    }

    override fun close() {
        inner.close()
    }

    override suspend fun awaitClosed() {
        inner.awaitClosed()
    }

    /** The ground radio writes its report straight to its serial side, towards the station. */
    private suspend fun report(peer: LinkPeer) {
        val status = RadioStatus.builder()
            .rssi(level(radio.rssi)).remrssi(level(radio.remrssi))
            .noise(level(radio.noise)).remnoise(level(radio.remnoise))
            .txbuf(uplink.freePercent()).rxerrors(0).fixed(0)
            .build()
        val frame = encoder.encode(status, SIK_SYSTEM, SIK_COMPONENT, reportSequence, version = 1)
        reportSequence = (reportSequence + 1) and 0xFF
        reports++
        inner.send(frame, peer)
    }

    private fun level(base: Int): Int = (base + random.nextInt(-radio.jitter, radio.jitter + 1)).coerceIn(0, 254)

    private companion object {
        const val SIK_SYSTEM = 51
        const val SIK_COMPONENT = 68

        /** A HEARTBEAT frame, as SiK's `check_heartbeat` recognises one: message id 0 in either version. */
        fun isHeartbeat(b: ByteArray): Boolean = when {
            b.size >= 6 && b[0] == 0xFE.toByte() -> b[5] == 0.toByte()
            b.size >= 10 && b[0] == 0xFD.toByte() -> b[7] == 0.toByte() && b[8] == 0.toByte() && b[9] == 0.toByte()
            else -> false
        }
    }
}
