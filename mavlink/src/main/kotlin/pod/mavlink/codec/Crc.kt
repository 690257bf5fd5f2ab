package pod.mavlink.codec

/**
 * CRC-16/MCRF4XX (the "X.25" checksum of the MAVLink spec): polynomial 0x1021 reflected, initial
 * value 0xFFFF, no final XOR. Computed byte-wise without a table: a frame is at most 280 bytes and
 * the shift-and-xor form is as fast as a table lookup on the JVM at that size.
 */
internal object Crc {
    const val INITIAL: Int = 0xFFFF

    /** [crc] extended by one byte [b] (only the low 8 bits of [b] are used). */
    fun accumulate(crc: Int, b: Int): Int {
        var t = (b xor crc) and 0xFF
        t = (t xor (t shl 4)) and 0xFF
        return ((crc ushr 8) xor (t shl 8) xor (t shl 3) xor (t ushr 4)) and 0xFFFF
    }

    /** [crc] extended by [length] bytes of [bytes] from [offset]. */
    fun accumulate(crc: Int, bytes: ByteArray, offset: Int, length: Int): Int {
        var c = crc
        for (i in offset until offset + length) c = accumulate(c, bytes[i].toInt())
        return c
    }

    /**
     * The MAVLink checksum of a frame: the bytes after the magic byte up to the end of the payload
     * ([length] bytes of [bytes] from [offset]), then the message's CRC_EXTRA.
     */
    fun frameChecksum(bytes: ByteArray, offset: Int, length: Int, crcExtra: Int): Int =
        accumulate(accumulate(INITIAL, bytes, offset, length), crcExtra)
}
