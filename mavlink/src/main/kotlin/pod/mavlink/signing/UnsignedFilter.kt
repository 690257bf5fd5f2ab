package pod.mavlink.signing

/**
 * Which unsigned frames a signed link still takes: the explicit callback of a [LinkSigning]
 * policy. It sees only the header's identity (message id, sender), never the payload, and runs on
 * the link's receive thread, so it must be quick and must not block.
 *
 * It decides only for frames that carry no signature: a frame with a signature that fails
 * verification is always refused. (ArduPilot's callback also forgives a bad signature on its
 * accepted list; Pod does not, since a bad signature on a signed link is a forgery or a fault.)
 */
public fun interface UnsignedFilter {
    /** Whether an unsigned frame of [messageId] from [systemId]/[componentId] is let through. */
    public fun allows(messageId: Int, systemId: Int, componentId: Int): Boolean

    /** The message ids a signed link may accept unsigned. */
    public companion object {
        /** RADIO_STATUS, the radio's link report. */
        public const val RADIO_STATUS: Int = 109

        /** RADIO, the ArduPilotMega dialect's older radio report. */
        public const val RADIO: Int = 166

        /**
         * The system id a SiK telemetry radio sends its own RADIO / RADIO_STATUS from: '3' (51),
         * component 'D' (68), for "3DR radio" (ArduPilot/SiK, Firmware/radio/mavlink.c,
         * RADIO_SOURCE_SYSTEM and RADIO_SOURCE_COMPONENT). A radio injects these frames itself and
         * holds no key, so they arrive unsigned on a signed link.
         */
        public const val SIK_SYSTEM_ID: Int = '3'.code

        /** The component id of a SiK radio's own reports ('D', 68); see [SIK_SYSTEM_ID]. */
        public const val SIK_COMPONENT_ID: Int = 'D'.code

        /** Nothing unsigned. */
        public val NONE: UnsignedFilter = UnsignedFilter { _, _, _ -> false }

        /**
         * RADIO_STATUS and RADIO from anyone: the list ArduPilot accepts unsigned on its telemetry
         * links (ArduPilot/ardupilot libraries/GCS_MAVLink/GCS_Signing.cpp, `accept_list` in
         * `accept_unsigned_callback`) and MAVProxy too (MAVProxy/modules/mavproxy_signing.py,
         * `allow_unsigned`).
         */
        public val RADIO_REPORTS: UnsignedFilter = UnsignedFilter { id, _, _ -> id == RADIO_STATUS || id == RADIO }

        /**
         * RADIO_STATUS and RADIO only from the SiK radio's own identity ([SIK_SYSTEM_ID] /
         * [SIK_COMPONENT_ID]): narrower than [RADIO_REPORTS], so nobody can pose unsigned as a
         * vehicle's radio with the vehicle's system id.
         */
        public val SIK_RADIO: UnsignedFilter = UnsignedFilter { id, sys, comp ->
            (id == RADIO_STATUS || id == RADIO) && sys == SIK_SYSTEM_ID && comp == SIK_COMPONENT_ID
        }
    }
}
