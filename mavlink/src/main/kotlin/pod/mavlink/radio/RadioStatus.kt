package pod.mavlink.radio

import pod.mavlink.codec.MavFrame

/**
 * The latest RADIO_STATUS (message 109) a telemetry radio injected into the link: the radio's own
 * view of the air link and of its transmit buffer.
 *
 * A SiK radio sends it from system [SIK_SYSTEM_ID] ('3'), component [SIK_COMPONENT_ID] ('D')
 * (ArduPilot/SiK Firmware/radio/mavlink.c, `RADIO_SOURCE_SYSTEM` / `RADIO_SOURCE_COMPONENT`), as a
 * MAVLink 1 frame, each time it passes a HEARTBEAT from its serial side to the air (packet.c,
 * `check_heartbeat`; tdm.c, `tdm_serial_loop` calls `MAVLink_report`): a ground radio reports
 * about once a second, on the ground station's own heartbeat. QGroundControl ignores it for link
 * liveness for that reason (VehicleLinkManager::mavlinkMessageReceived): it proves the radio is
 * there, not the vehicle.
 */
public data class RadioStatus(
    /** Who sent it: 51 for a SiK radio. */
    public val systemId: Int,
    /** Its component: 68 for a SiK radio. */
    public val componentId: Int,
    /** Local signal strength (device units, SiK: averaged RSSI register, 0..254; 255 unknown). */
    public val rssi: Int,
    /** The remote radio's signal strength, as it last reported it over the air. */
    public val remrssi: Int,
    /**
     * Free space of the radio's transmit buffer, percent: SiK reports how much of its serial
     * receive FIFO (2048 bytes, serial.c `rx_buf`) is free, in steps of 8 bytes
     * (serial.c, `serial_read_space`). What a ground station sends waits there for the air.
     */
    public val txbuf: Int,
    /** Local background noise (device units). */
    public val noise: Int,
    /** The remote radio's background noise. */
    public val remnoise: Int,
    /** Air packets received with errors, since the radio booted. */
    public val rxerrors: Int,
    /** Air packets repaired by error correction, since the radio booted. */
    public val fixed: Int,
) {
    /** A one-line summary for people: `rssi 180/175 noise 40/38 txbuf 93%`. */
    override fun toString(): String = "rssi $rssi/$remrssi noise $noise/$remnoise txbuf $txbuf% (radio $systemId/$componentId)"

    /** The numbers that identify a radio's status report on the link. */
    public companion object {
        /** RADIO_STATUS's message id. */
        public const val MESSAGE_ID: Int = 109

        /** The system id SiK radios report from: ASCII '3' (for "3DR radio"). */
        public const val SIK_SYSTEM_ID: Int = 51

        /** The component id SiK radios report from: ASCII 'D'. */
        public const val SIK_COMPONENT_ID: Int = 68

        /** [message] (an io.dronefleet RadioStatus) as sent in [frame], or null for any other message. */
        internal fun of(frame: MavFrame, message: Any?): RadioStatus? {
            val m = message as? io.dronefleet.mavlink.common.RadioStatus ?: return null
            return RadioStatus(frame.systemId, frame.componentId, m.rssi(), m.remrssi(), m.txbuf(), m.noise(), m.remnoise(), m.rxerrors(), m.fixed())
        }
    }
}

