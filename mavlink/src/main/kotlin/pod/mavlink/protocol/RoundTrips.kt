package pod.mavlink.protocol

import pod.mavlink.VehicleTiming
import pod.mavlink.command.CommandRoundTrip
import pod.mavlink.mission.RoundTripEstimator

/**
 * The round-trip estimates of one vehicle, one per protocol family, shared by every exchange with
 * it so that each starts from what the previous one measured; each is bounded by its service's
 * part of [timing], fixed for the vehicle's life, and from below by [linkFloorNanos], what the
 * link allows now (a paced telemetry radio's few frame times; 0 on other links).
 */
internal class RoundTrips(timing: VehicleTiming, linkFloorNanos: () -> Long = { 0L }) {
    private val mission = RoundTripEstimator(timing.transfers, linkFloorNanos)

    /** Commands' estimate. */
    val command: CommandRoundTrip = CommandRoundTrip(timing.commands, linkFloorNanos)

    /** Parameter exchanges' estimate. */
    val param: CommandRoundTrip = CommandRoundTrip(timing.params, linkFloorNanos)

    /** Mission transfers' estimate; any backing off from an earlier transfer is dropped. */
    @Synchronized
    fun mission(): RoundTripEstimator = mission.also { it.progressed() }
}
