package pod.sim

/**
 * How a simulated vehicle tells the ground what a photo detected: a simulator convention, not a
 * MAVLink one (a real vehicle runs inference on a companion computer and reports in its own way).
 *
 * The photo's CAMERA_IMAGE_CAPTURED, which the vehicle sends anyway, carries the detections in its
 * `file_url` field: `pod-sim://photo/<image_index>?objects=<id>,<id>,…` with the [pod.sim.world.SimObject]
 * ids in ascending order (`objects=` empty when nothing was seen). The field holds 205 characters;
 * ids that do not fit are left off and the URL ends with `&more=<count left off>` instead, so a
 * reader can tell a full list from a cut one. One message per photo means a lost datagram loses a
 * photo's detections with its capture report, never half of them.
 */
public object SimDetections {
    private const val PREFIX = "pod-sim://photo/"
    private const val FIELD = 205

    /** The `file_url` for photo [index] that detected [ids]. */
    public fun fileUrl(index: Int, ids: List<Int>): String {
        val sorted = ids.sorted()
        val base = "$PREFIX$index?objects="
        val full = base + sorted.joinToString(",")
        if (full.length <= FIELD) return full
        // Keep as many ids as fit together with the "&more=N" suffix.
        var kept = sorted.size
        while (kept > 0) {
            val text = base + sorted.take(kept).joinToString(",") + "&more=${sorted.size - kept}"
            if (text.length <= FIELD) return text
            kept--
        }
        return base + "&more=${sorted.size}"
    }

    /** The detections a `file_url` reports, or null when it is not this convention's. */
    public fun parse(fileUrl: String): Detections? {
        if (!fileUrl.startsWith(PREFIX)) return null
        val rest = fileUrl.removePrefix(PREFIX)
        val index = rest.substringBefore('?').toIntOrNull() ?: return null
        val query = rest.substringAfter('?', "").split('&').associate { it.substringBefore('=') to it.substringAfter('=', "") }
        val objects = query["objects"] ?: return null
        val ids = if (objects.isEmpty()) emptyList() else objects.split(',').map { it.toIntOrNull() ?: return null }
        val more = query["more"]?.let { it.toIntOrNull() ?: return null } ?: 0
        return Detections(index, ids, more)
    }

    /** What one photo detected, as read from its `file_url`. */
    public data class Detections(
        /** The photo's image_index. */
        public val imageIndex: Int,
        /** Ids of the objects detected (all of them when [leftOff] is 0). */
        public val ids: List<Int>,
        /** How many more were detected but did not fit the field. */
        public val leftOff: Int = 0,
    )
}
