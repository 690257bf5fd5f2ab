package pod.mavlink.route

import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec

/**
 * Reads a frame's target_system and target_component straight from its payload bytes, at offsets
 * looked up once per message id in the codec's wire plan: a router needs these two bytes, not a
 * decoded message.
 *
 * As mavlink-router does (mavlink-router/mavlink-router, src/mavlink-router/endpoint.cpp,
 * `Endpoint::read_msg`): a field past the end of a MAVLink 2 payload was truncated away as a
 * trailing zero, so it reads 0; a message without the field, or of an id the dialect does not
 * know, has no target ([NONE]). Thread-safe: the cache is an int per id, written with the same
 * value by whichever thread computes it first.
 */
internal class FrameTargets(private val codec: MessageCodec = MessageCodec.Default) {
    // Per message id below CACHED_IDS: (system offset + 1) | (component offset + 1) shl 16, 0 = none;
    // UNKNOWN until first asked.
    private val offsets = IntArray(CACHED_IDS) { UNKNOWN }

    /** The frame's target system (0 = broadcast), or [NONE] when its message has no such field. */
    fun system(frame: MavFrame): Int = read(frame, packed(frame.messageId) and 0xFFFF)

    /** The frame's target component (0 = every component), or [NONE] when its message has no such field. */
    fun component(frame: MavFrame): Int = read(frame, packed(frame.messageId) ushr 16)

    private fun read(frame: MavFrame, offsetPlusOne: Int): Int {
        if (offsetPlusOne == 0) return NONE
        val at = offsetPlusOne - 1
        return if (at < frame.payload.size) frame.payload[at].toInt() and 0xFF else 0
    }

    private fun packed(messageId: Int): Int {
        if (messageId !in 0 until CACHED_IDS) return compute(messageId)
        val cached = offsets[messageId]
        if (cached != UNKNOWN) return cached
        return compute(messageId).also { offsets[messageId] = it }
    }

    private fun compute(messageId: Int): Int {
        val plan = codec.planOf(messageId) ?: return 0
        fun offsetOf(name: String): Int =
            plan.fields.firstOrNull { it.name == name && it.unitSize == 1 && it.count == 1 }?.let { it.offset + 1 } ?: 0
        return offsetOf("targetSystem") or (offsetOf("targetComponent") shl 16)
    }

    companion object {
        /** What [system] and [component] say for a message that has no target field. */
        const val NONE: Int = -1

        /** Message ids with a cache slot; MAVLink 2 ids in use stay below this. */
        private const val CACHED_IDS = 65_536
        private const val UNKNOWN = -1
    }
}
