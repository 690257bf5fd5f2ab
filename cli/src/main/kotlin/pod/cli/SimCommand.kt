package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.transformAll
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.choice
import com.github.ajalt.clikt.parameters.types.double
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.runBlocking
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.link.LinkAddress
import pod.sim.FanOutOpener
import pod.sim.LinkOpener
import pod.sim.SimFleet
import pod.sim.SimVehicleConfig
import pod.sim.radio.SikRadio

private const val DEFAULT_OUT = "udpout:127.0.0.1:14550"

/** `pod sim`: simulated vehicles sending to a ground station, until interrupted. */
internal class SimCommand(private val out: Output) : CliktCommand(name = "sim") {
    private val vehicles by option("--vehicles", help = "how many vehicles").int().restrictTo(1..254).default(1)
    private val targets by option(
        "--out",
        help = "where telemetry goes, like SITL's --out (repeat it for several ground stations); with udpin:HOST:PORT the vehicles listen, vehicle i on PORT+i; " +
            "serial:///dev/ttyUSB0:57600 (one vehicle) talks over a serial port",
    ).transformAll(defaultForHelp = DEFAULT_OUT) { it.ifEmpty { listOf(DEFAULT_OUT) } }
    private val target: String get() = targets.first()
    private val type by option("--type", help = "airframe").choice("quad" to VehicleType.QUADROTOR, "plane" to VehicleType.FIXED_WING)
        .default(VehicleType.QUADROTOR, defaultForHelp = "quad")
    private val autopilot by option("--autopilot", help = "autopilot flavour")
        .choice("ardupilot" to Autopilot.ARDUPILOT, "px4" to Autopilot.PX4).default(Autopilot.ARDUPILOT, defaultForHelp = "ardupilot")
    // --time-scale as in pod run, survey, demo and queue serve; --speedup, its first name, still works.
    private val speedup by option("--time-scale", "--speedup", metavar = "X", help = "simulated seconds per real second (--speedup: the same)")
        .double().restrictTo(0.01..1000.0).default(1.0)
    private val sysid by option("--sysid", help = "system id of the first vehicle").int().restrictTo(1..254).default(1)
    private val json by option("--json", help = "JSON lines instead of text").flag()
    private val keyFile by keyFileOption()
    private val radio by option("--radio", metavar = "BAUD", help = "emulate a SiK radio pair at BAUD (e.g. 57600) between each vehicle and the ground")
        .int().restrictTo(1_200..2_000_000)

    override fun help(context: Context): String = "Run simulated MAVLink vehicles until interrupted."

    override fun run() = runBlocking {
        val addresses = reportingLinkErrors { targets.map(LinkAddress::parse) }
        if (sysid + vehicles - 1 > 254) badInput("--sysid $sysid with --vehicles $vehicles goes past system id 254")
        for ((text, address) in targets.zip(addresses)) {
            if (address is LinkAddress.UdpIn && address.port != 0 && address.port + vehicles - 1 > 65535) {
                badInput("--out $text with --vehicles $vehicles needs ports ${address.port}..${address.port + vehicles - 1}, past 65535")
            }
            if (address is LinkAddress.Serial && vehicles > 1) badInput("--out $text: a serial port carries one simulated vehicle, not $vehicles")
        }
        val fleet = reportingLinkErrors {
            SimFleet.start(
                vehicles, this,
                SimVehicleConfig(
                    systemId = sysid, type = type, autopilot = autopilot, gcs = target, timeScale = speedup,
                    signingKey = signingKey(keyFile), radio = radio?.let { SikRadio(baud = it) },
                ),
                openLink = if (addresses.size > 1) FanOutOpener(addresses) else LinkOpener.Udp,
            )
        }
        for (v in fleet.vehicles) {
            val c = v.config
            val own = LinkAddress.parse(c.gcs)
            out.line(
                if (json) {
                    EventJson.encode(Event.Started(c.systemId, c.type.name, c.autopilot.name, v.localPort, own.toString()))
                } else {
                    "vehicle ${c.systemId}: ${c.type.name.lowercase()} on ${c.autopilot.name.lowercase()}, " +
                        when (own) {
                            is LinkAddress.UdpIn -> "listening on ${own.copy(port = v.localPort ?: own.port)}"
                            is LinkAddress.Serial -> "on $own"
                            else -> "sending from port ${v.localPort} to $own"
                        } +
                        addresses.drop(1).joinToString("") { ", and to $it" }
                },
            )
        }
        try {
            awaitCancellation()
        } finally {
            fleet.stop()
        }
    }
}
