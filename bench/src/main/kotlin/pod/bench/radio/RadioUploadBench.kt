package pod.bench.radio

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import pod.bench.percentile
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.VehicleTiming
import pod.mavlink.mission.TransferTiming
import kotlin.time.Duration.Companion.milliseconds
import pod.mavlink.radio.RadioPacing
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.WplFile
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.radio.RadioLink
import pod.sim.radio.SikRadio
import java.io.File
import java.net.DatagramSocket
import java.util.Locale
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * A 200-item mission upload into a simulated ArduCopter behind an emulated 57600-baud SiK pair
 * ([RadioLink]) on loopback UDP, by Pod's GroundStation (in this process, pacing on the radio's
 * reports), pymavlink (bench/pymavlink_radio_upload.py) and MAVProxy (`wp load` of the same QGC
 * WPL file), a fresh vehicle per run, [RUNS] runs each, in one run of this program. Each run also
 * counts the bytes the radio carried during the upload; their wire time at baud / 10 bytes per
 * second is the link's own limit for that run. Every run is bounded (120 s).
 *
 * Arguments: `PYTHON MAVPROXY_PY WPL_FILE [RUNS]`.
 */
fun main(args: Array<String>) {
    require(args.size >= 3) { "usage: RadioUploadBenchKt PYTHON MAVPROXY_PY WPL_FILE [RUNS]" }
    val (python, mavproxy, wpl) = args.take(3).map(::File)
    val runs = args.getOrNull(3)?.toInt() ?: RUNS
    val items = WplFile.read(wpl.toPath())
    println("== radio upload: ${items.size} items, ${RADIO.baud} baud, ${RADIO.bufferBytes}-byte buffers, $runs runs per ground station")
    val results = linkedMapOf<String, MutableList<Run>>()
    for (run in 1..runs) {
        for ((name, upload) in listOf<Pair<String, (Int, RadioLink) -> Double>>(
            "Pod" to { port, _ -> pod(port, items, RadioPacing()) },
            "Pod, pacing off" to { port, _ -> pod(port, items, RadioPacing.Off) },
            "Pod, min timeout 60 ms" to { port, _ -> pod(port, items, RadioPacing(), TransferTiming(minTimeout = 60.milliseconds)) },
            "pymavlink" to { port, _ -> PythonPeers.pymavlink(python, port, wpl) },
            "MAVProxy" to { port, _ -> PythonPeers.mavproxy(python, mavproxy, port, wpl, items.size) },
        )) {
            val r = runCatching { withVehicle(run) { port, radio -> measure(radio) { upload(port, radio) } } }
                .getOrElse { Run(Double.NaN, 0, 0, 0, it.message ?: it.toString()) }
            println("$name run $run: $r")
            results.getOrPut(name) { ArrayList() } += r
        }
    }
    println()
    println("| ground station | runs ok | upload s median (min–max) | bytes up / down | link limit s | × limit | bytes dropped |")
    println("|---|---:|---:|---:|---:|---:|---:|")
    for ((name, rs) in results) {
        val ok = rs.filter { it.error == null }
        if (ok.isEmpty()) {
            println("| $name | 0/${rs.size} | – | – | – | – | – |")
            continue
        }
        val t = percentile(ok.map { it.seconds }, 50.0)
        val up = percentile(ok.map { it.up.toDouble() }, 50.0)
        val down = percentile(ok.map { it.down.toDouble() }, 50.0)
        val limit = percentile(ok.map { it.limitSeconds }, 50.0)
        println(
            "| $name | ${ok.size}/${rs.size} | ${f(t)} (${f(ok.minOf { it.seconds })}–${f(ok.maxOf { it.seconds })}) | " +
                "${up.toLong()} / ${down.toLong()} | ${f(limit)} | ${"%.2f".format(Locale.ROOT, t / limit)} | ${ok.sumOf { it.dropped }} |",
        )
    }
}

private const val RUNS = 5
private val RADIO = SikRadio(baud = 57_600)

/** One upload: its time, the bytes the radio carried each way meanwhile, the bytes it dropped, or why it failed. */
private class Run(val seconds: Double, val up: Long, val down: Long, val dropped: Long, val error: String? = null) {
    /** Wire time of the bytes carried: one item in flight at a time, so the two directions add up. */
    val limitSeconds: Double get() = (up + down) / RADIO.bytesPerSecond

    override fun toString(): String =
        error?.let { "FAILED ($it)" } ?: "${f(seconds)} s, $up B up, $down B down, limit ${f(limitSeconds)} s, dropped $dropped"
}

private fun f(v: Double) = "%.3f".format(Locale.ROOT, v)

private fun measure(radio: RadioLink, upload: () -> Double): Run {
    val up0 = radio.uplinkCarried
    val down0 = radio.downlinkCarried
    val dropped0 = radio.uplinkDropped + radio.downlinkDropped
    val seconds = upload()
    return Run(seconds, radio.uplinkCarried - up0, radio.downlinkCarried - down0, radio.uplinkDropped + radio.downlinkDropped - dropped0)
}

/** A fresh simulated ArduCopter behind the radio pair, sending to a free loopback port; stopped after [block]. */
private fun <T> withVehicle(seed: Int, block: (Int, RadioLink) -> T): T = runBlocking(Dispatchers.Default) {
    val port = DatagramSocket(0).use { it.localPort }
    val sim = SimVehicle(SimVehicleConfig(systemId = 1, gcs = "udpout://127.0.0.1:$port", radio = RADIO.copy(seed = seed.toLong())))
    sim.start(this)
    try {
        block(port, sim.radioLink!!)
    } finally {
        sim.stop()
    }
}

/** Pod's upload, timed from the call to its return (MISSION_ACK ACCEPTED), after the radio's first report. */
private fun pod(port: Int, items: List<MissionItem>, pacing: RadioPacing, transfers: TransferTiming = TransferTiming()): Double = runBlocking(Dispatchers.Default) {
    val gcs = GroundStation.open("udpin://127.0.0.1:$port", this, GroundStationConfig(radioPacing = pacing, vehicleTiming = VehicleTiming(transfers = transfers)))
    try {
        val vehicle = withTimeout(30.seconds) { gcs.vehicles.first { 1 in it } }.getValue(1)
        withTimeout(10.seconds) { gcs.radio.filterNotNull().first() }
        val started = TimeSource.Monotonic.markNow()
        withTimeout(120.seconds) { vehicle.mission.upload(items) }
        started.elapsedNow().inWholeMicroseconds / 1e6
    } finally {
        gcs.closeAndAwait()
    }
}
