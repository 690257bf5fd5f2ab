package pod.mavlink.codec

/** Sizes and markers of MAVLink 1 and 2 frames, as the spec fixes them. */
internal object FrameLayout {
    const val MAGIC_V1: Int = 0xFE
    const val MAGIC_V2: Int = 0xFD

    /** Magic, length, sequence, system, component, 8-bit message id. */
    const val HEADER_V1: Int = 6

    /** Magic, length, incompat flags, compat flags, sequence, system, component, 24-bit message id. */
    const val HEADER_V2: Int = 10
    const val CHECKSUM: Int = 2

    /** Link id, 48-bit timestamp, 48-bit truncated SHA-256 signature. */
    const val SIGNATURE: Int = 13
    const val FLAG_SIGNED: Int = 0x01
    const val MAX_PAYLOAD: Int = 255
    const val MAX_V1_MESSAGE_ID: Int = 0xFF
    const val MAX_V2_MESSAGE_ID: Int = 0xFFFFFF

    /** The longest possible frame: a signed MAVLink 2 frame with a 255-byte payload. */
    const val MAX_FRAME: Int = HEADER_V2 + MAX_PAYLOAD + CHECKSUM + SIGNATURE
}

/** The [size]-byte little-endian integer at [offset], zero-extended to a Long ([size] 1..8). */
internal fun ByteArray.readUnsignedLe(offset: Int, size: Int): Long = when (size) {
    1 -> (this[offset].toLong() and 0xFF)
    2 -> (this[offset].toLong() and 0xFF) or ((this[offset + 1].toLong() and 0xFF) shl 8)
    4 -> readInt32Le(offset).toLong() and 0xFFFF_FFFFL
    8 -> (readInt32Le(offset).toLong() and 0xFFFF_FFFFL) or (readInt32Le(offset + 4).toLong() shl 32)
    else -> {
        var value = 0L
        for (i in 0 until size) value = value or ((this[offset + i].toLong() and 0xFF) shl (8 * i))
        value
    }
}

/** The [size]-byte little-endian integer at [offset], sign-extended to a Long ([size] 1..8). */
internal fun ByteArray.readSignedLe(offset: Int, size: Int): Long = when (size) {
    1 -> this[offset].toLong()
    2 -> ((this[offset].toInt() and 0xFF) or (this[offset + 1].toInt() shl 8)).toShort().toLong()
    4 -> readInt32Le(offset).toLong()
    8 -> readUnsignedLe(offset, 8)
    else -> (readUnsignedLe(offset, size) shl (64 - 8 * size)) shr (64 - 8 * size)
}

/** The 4-byte little-endian integer at [offset]. */
internal fun ByteArray.readInt32Le(offset: Int): Int =
    (this[offset].toInt() and 0xFF) or
        ((this[offset + 1].toInt() and 0xFF) shl 8) or
        ((this[offset + 2].toInt() and 0xFF) shl 16) or
        (this[offset + 3].toInt() shl 24)

/** Writes the low [size] bytes of [value] at [offset], little-endian. */
internal fun ByteArray.writeLe(offset: Int, size: Int, value: Long) {
    for (i in 0 until size) this[offset + i] = (value ushr (8 * i)).toByte()
}
