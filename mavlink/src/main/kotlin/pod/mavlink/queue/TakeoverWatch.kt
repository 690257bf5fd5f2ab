package pod.mavlink.queue

import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import pod.core.PodException
import pod.core.platform.AutopilotTookControl
import pod.core.vehicle.Severity
import pod.mavlink.MavlinkVehicle
import pod.mavlink.telemetry.RecentNotices

/**
 * Watches a flight Pod steers in modes of its own choosing (the guided mode, its hold, a landing
 * or return it asked for) and ends it as soon as the vehicle, once in one of them, is armed in any
 * other mode: its autopilot took control (a fence breach, a failsafe) or a pilot did. Steering on
 * would override them: the queue's next DO_REPOSITION (change-mode flag) would take a copter out of
 * its fence RTL. The mode the vehicle was in before Pod's first command (a take-off, a mission it
 * just flew) is not a takeover. [allowed] is updated by the flight before it changes mode itself.
 */
internal class TakeoverWatch(private val vehicle: MavlinkVehicle, initial: Set<String>) {
    /** The modes Pod put or may put the vehicle in now. */
    @Volatile
    var allowed: Set<String> = initial

    /** Returns only by throwing [QueueInterrupted] once the vehicle is armed in a mode not [allowed]. */
    suspend fun watch(): Nothing = coroutineScope {
        val heard = RecentNotices()
        val listening = launch { vehicle.statusTexts.collect { if (it.severity <= Severity.NOTICE) heard.add(it.text, vehicle.clock.markNow()) } }
        val modes = combine(vehicle.telemetry.mode, vehicle.telemetry.armed) { m, armed -> m?.name?.takeIf { armed } }
        modes.first { it != null && it in allowed }
        val mode = modes.first { it != null && it !in allowed }!!
        listening.cancel()
        throw QueueInterrupted(vehicle.systemId, mode, heard.within(TEXTS_BEFORE))
    }

    private companion object {
        /** How long before the switch a notice may come and still be its reason. */
        val TEXTS_BEFORE = 3.seconds
    }
}

/**
 * The vehicle left the modes its queue flight (a queue, waypoint actions, a survey) steered it in
 * for [mode]: its autopilot took control (a failsafe, a fence breach) or a pilot did. [said] is what
 * it reported just before. The engine leaves it in that mode ([AutopilotTookControl]).
 */
public class QueueInterrupted(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** The mode it switched to. */
    public val mode: String,
    /** Its notices, warnings and errors (STATUSTEXT) from shortly before, oldest first. */
    public val said: List<String> = emptyList(),
) : PodException(
    "vehicle $systemId left its queue flight: it switched to $mode" +
        (if (said.isEmpty()) "" else "; it said: " + said.joinToString("; ") { "\"$it\"" }),
),
    AutopilotTookControl
