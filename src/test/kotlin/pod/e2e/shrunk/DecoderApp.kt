package pod.e2e.shrunk

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.minimal.Heartbeat
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.MessageCodec

/**
 * A tiny app for ShrunkDecoderSpec to shrink with R8: decodes the MAVLink frames given as hex
 * arguments through Pod's decoder and codec into io.dronefleet messages and prints their fields,
 * one line per frame. It lives in a package of its own so the spec can take its classes alone.
 */
fun main(args: Array<String>) {
    val decoder = FrameDecoder()
    for (hex in args) {
        val bytes = ByteArray(hex.length / 2) { hex.substring(2 * it, 2 * it + 2).toInt(16).toByte() }
        decoder.feed(bytes) { frame -> println(describe(frame.messageId, MessageCodec.Default.decode(frame))) }
    }
}

/** One line naming the fields of [message] (decoded from a frame of [messageId]). */
fun describe(messageId: Int, message: Any?): String = when (message) {
    is Heartbeat -> "HEARTBEAT type=${message.type().entry()} autopilot=${message.autopilot().entry()} " +
        "customMode=${message.customMode()} status=${message.systemStatus().entry()} version=${message.mavlinkVersion()}"
    is GlobalPositionInt -> "GLOBAL_POSITION_INT time=${message.timeBootMs()} lat=${message.lat()} lon=${message.lon()} " +
        "alt=${message.alt()} relativeAlt=${message.relativeAlt()} vx=${message.vx()} hdg=${message.hdg()}"
    null -> "message $messageId not decoded"
    else -> "message $messageId decoded as ${message.javaClass.name}"
}
