package pod.sim.radio

/**
 * A pair of SiK telemetry radios (one on the ground station's side, one on the vehicle's) as a
 * [RadioLink] emulates them, after ArduPilot/SiK's firmware (Firmware/radio):
 *
 * - Each radio buffers what its serial side gives it until the air takes it: 2048 bytes
 *   (serial.c, `rx_buf`); bytes that find the buffer full are dropped and counted
 *   (`serial_interrupt`, `errors.serial_rx_overflow`). A frame cut there fails its CRC downstream.
 * - The buffer drains at [baud] / 10 bytes a second (a serial byte is 10 bits: start, 8 data,
 *   stop). SiK's default air rate (AIR_SPEED 64 kbit/s, parameters.c) is above its default serial
 *   speed (SERIAL_SPEED 57, i.e. 57600), but the air link is time-division duplex with error
 *   correction and framing, so in use the air carries less than the serial line: this emulation
 *   takes the serial rate as the pace of each direction, which is the best case for the sender.
 * - Each time a radio forwards a HEARTBEAT from its serial side, it injects RADIO_STATUS (id 109,
 *   MAVLink 1, from system 51 '3', component 68 'D') back to that side (packet.c `check_heartbeat`,
 *   tdm.c `tdm_serial_loop`, mavlink.c `MAVLink_report`): a ground station hears its radio once
 *   per heartbeat it sends. `txbuf` is the free part of the buffer in percent, in 8-byte steps
 *   (serial.c `serial_read_space`).
 *
 * [rssi], [remrssi], [noise] and [remnoise] are the levels the radios report, varied by ±[jitter]
 * from a generator seeded with [seed], so a run is the same every time.
 */
public data class SikRadio(
    /** Serial speed of both radios, bits per second (57600 is SiK's default). */
    public val baud: Int = 57_600,
    /** Bytes each radio buffers before the air takes them. */
    public val bufferBytes: Int = 2_048,
    /** Signal strength the ground radio reports (SiK units, 0..254). */
    public val rssi: Int = 180,
    /** Signal strength the vehicle's radio reports back. */
    public val remrssi: Int = 175,
    /** Background noise at the ground radio. */
    public val noise: Int = 40,
    /** Background noise at the vehicle's radio. */
    public val remnoise: Int = 38,
    /** Largest random change of each level from one report to the next. */
    public val jitter: Int = 3,
    /** Seed of the levels' variation. */
    public val seed: Long = 1,
) {
    init {
        require(baud in 1_200..2_000_000) { "baud must be in 1200..2000000, was $baud" }
        require(bufferBytes in 64..1_048_576) { "bufferBytes must be in 64..1048576, was $bufferBytes" }
        listOf("rssi" to rssi, "remrssi" to remrssi, "noise" to noise, "remnoise" to remnoise).forEach { (name, v) ->
            require(v in 0..254) { "$name must be in 0..254, was $v" }
        }
        require(jitter in 0..50) { "jitter must be in 0..50, was $jitter" }
    }

    /** Bytes per second each direction carries: [baud] / 10. */
    public val bytesPerSecond: Double get() = baud / 10.0
}
