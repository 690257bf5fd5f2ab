package pod.mavlink.fuzz

import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.FrameLayout
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec

/** Bytes [frame] took on the wire: header, payload, checksum and signature block. */
internal fun wireLength(frame: MavFrame): Int =
    (if (frame.version == 2) FrameLayout.HEADER_V2 else FrameLayout.HEADER_V1) + frame.payload.size +
        FrameLayout.CHECKSUM + (frame.signature?.size ?: 0)

/**
 * What every delivered frame must be, whatever the input: fields in their wire ranges, a payload of
 * at most 255 bytes, a signature block exactly when a MAVLink 2 frame says it is signed; and its
 * payload must decode (as the station decodes every frame it routes) without throwing.
 */
internal fun checkFrame(frame: MavFrame, codec: MessageCodec) {
    property(frame.version == 1 || frame.version == 2) { "version ${frame.version}" }
    property(frame.sequence in 0..255 && frame.systemId in 0..255 && frame.componentId in 0..255) { "header field out of range: $frame" }
    property(frame.messageId in 0..(if (frame.version == 1) 255 else 0xFFFFFF)) { "message id out of range: $frame" }
    property(frame.payload.size <= FrameLayout.MAX_PAYLOAD) { "payload of ${frame.payload.size} bytes" }
    val signed = frame.version == 2 && frame.incompatFlags and FrameLayout.FLAG_SIGNED != 0
    property(signed == (frame.signature != null)) { "signed flag and signature disagree: $frame" }
    property(frame.signature == null || frame.signature!!.size == FrameLayout.SIGNATURE) { "signature of ${frame.signature?.size} bytes" }
    codec.decode(frame)
}

/**
 * Feeds [bytes] to [decoder] as one call and checks its counters account for every byte: what it
 * held before plus [bytes] is what it delivered in frames, skipped, and holds now (under one frame).
 * Returns the frames delivered.
 */
internal fun feedAccounted(decoder: FrameDecoder, bytes: ByteArray, codec: MessageCodec, offset: Int = 0, length: Int = bytes.size): List<MavFrame> {
    val pendingBefore = decoder.pendingBytes
    val skippedBefore = decoder.stats.skippedBytes
    val framesBefore = decoder.stats.frames
    val frames = ArrayList<MavFrame>(4)
    var frameBytes = 0L
    decoder.feed(bytes, offset, length) { frame ->
        checkFrame(frame, codec)
        frameBytes += wireLength(frame)
        frames += frame
    }
    val skipped = decoder.stats.skippedBytes - skippedBefore
    val pending = decoder.pendingBytes
    property(pendingBefore.toLong() + length == frameBytes + skipped + pending) {
        "bytes unaccounted for: $pendingBefore held + $length fed ≠ $frameBytes in frames + $skipped skipped + $pending held"
    }
    property(pending < FrameLayout.MAX_FRAME) { "holds $pending bytes, more than a frame" }
    property(decoder.stats.frames - framesBefore == frames.size.toLong()) { "frame counter moved ${decoder.stats.frames - framesBefore} for ${frames.size} frames" }
    return frames
}

/** [frame] as wire bytes again (with the checksum it arrived with): equal bytes mean equal frames. */
internal fun FrameEncoder.asWire(frame: MavFrame): ByteArray = wireBytes(frame)
