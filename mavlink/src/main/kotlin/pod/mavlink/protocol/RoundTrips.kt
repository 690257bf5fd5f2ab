package pod.mavlink.protocol

import pod.mavlink.command.CommandRoundTrip
import pod.mavlink.command.CommandTiming
import pod.mavlink.mission.RoundTripEstimator
import pod.mavlink.mission.TransferTiming

/**
 * The round-trip estimates of one vehicle, one per protocol family, shared by every exchange with
 * it so that each starts from what the previous one measured. An estimate is made anew when the
 * timing it is bounded by changes (a service's `timing` was replaced).
 */
internal class RoundTrips {
    private var mission: Pair<TransferTiming, RoundTripEstimator>? = null
    private var command: Pair<CommandTiming, CommandRoundTrip>? = null
    private var param: Pair<CommandTiming, CommandRoundTrip>? = null

    /** Mission transfers' estimate, for [timing]; any backing off from an earlier transfer is dropped. */
    @Synchronized
    fun mission(timing: TransferTiming): RoundTripEstimator {
        val kept = mission?.takeIf { it.first == timing }?.second ?: RoundTripEstimator(timing).also { mission = timing to it }
        return kept.also { it.progressed() }
    }

    /** Commands' estimate, for [timing]. */
    @Synchronized
    fun command(timing: CommandTiming): CommandRoundTrip =
        command?.takeIf { it.first == timing }?.second ?: CommandRoundTrip(timing).also { command = timing to it }

    /** Parameter exchanges' estimate, for [timing]. */
    @Synchronized
    fun param(timing: CommandTiming): CommandRoundTrip =
        param?.takeIf { it.first == timing }?.second ?: CommandRoundTrip(timing).also { param = timing to it }
}
