package pod.sim

import kotlinx.coroutines.CoroutineScope
import pod.core.time.Timebase
import pod.core.units.m
import pod.mavlink.link.LinkAddress

/**
 * Several [SimVehicle]s with distinct system ids, parked in a row east of the home of the
 * configuration they were started from ([start]), so their positions differ.
 */
public class SimFleet private constructor(
    /** The vehicles, in system-id order. */
    public val vehicles: List<SimVehicle>,
) {
    /** The vehicle with [systemId]; throws NoSuchElementException when the fleet has none. */
    public operator fun get(systemId: Int): SimVehicle =
        vehicles.firstOrNull { it.config.systemId == systemId }
            ?: throw NoSuchElementException("no simulated vehicle with system id $systemId in ${vehicles.map { it.config.systemId }}")

    /** Stops every vehicle. */
    public fun stop() {
        vehicles.forEach { it.stop() }
    }

    /** Starts simulated fleets. */
    public companion object {
        /**
         * Starts [count] vehicles in [scope]: system ids from [firstSystemId], each a copy of [base]
         * with its home [spacing] metres east of the previous one.
         *
         * When [base] listens (`udpin://host:port`, port not 0), vehicle i listens on port + i, as
         * SITL's instances each take their own port: one port cannot be bound twice. A serial
         * [base] carries one vehicle (a device is opened once).
         *
         * Every vehicle reads [timebase] and opens its link with [openLink] (see [SimVehicle]).
         */
        public suspend fun start(
            count: Int,
            scope: CoroutineScope,
            base: SimVehicleConfig = SimVehicleConfig(systemId = 1),
            firstSystemId: Int = base.systemId,
            spacing: Double = 10.0,
            timebase: Timebase = Timebase.System,
            openLink: LinkOpener = LinkOpener.Udp,
        ): SimFleet {
            require(count in 1..254) { "count must be in 1..254, was $count" }
            require(firstSystemId in 1..254 && firstSystemId + count - 1 <= 254) {
                "system ids $firstSystemId..${firstSystemId + count - 1} must lie within 1..254"
            }
            val own = LinkAddress.parse(base.gcs)
            require(own !is LinkAddress.Serial || count == 1) { "a serial port (${base.gcs}) carries one simulated vehicle, not $count" }
            val listen = own as? LinkAddress.UdpIn
            if (listen != null && listen.port != 0) {
                require(listen.port + count - 1 <= 65535) { "ports ${listen.port}..${listen.port + count - 1} for $count listening vehicles go past 65535" }
            }
            val vehicles = (0 until count).map { i ->
                SimVehicle(
                    base.copy(
                        systemId = firstSystemId + i,
                        gcs = if (listen != null && listen.port != 0) listen.copy(port = listen.port + i).toString() else base.gcs,
                        home = base.home.offset(north = 0.m, east = (spacing * i).m),
                    ),
                    timebase = timebase,
                    openLink = openLink,
                )
            }
            val fleet = SimFleet(vehicles)
            try {
                vehicles.forEach { it.start(scope) }
            } catch (e: Throwable) {
                fleet.stop()
                throw e
            }
            return fleet
        }
    }
}
