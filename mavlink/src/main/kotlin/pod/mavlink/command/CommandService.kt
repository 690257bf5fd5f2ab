package pod.mavlink.command

import io.dronefleet.mavlink.common.CommandAck
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.launch
import kotlinx.coroutines.selects.onTimeout
import kotlinx.coroutines.selects.select
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import pod.mavlink.MavlinkVehicle
import pod.mavlink.exchange
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.Duration.Companion.seconds

/**
 * Sends commands to one vehicle and waits for their answers (COMMAND_LONG / COMMAND_INT and
 * COMMAND_ACK).
 *
 * An acknowledgement names only the command, so two exchanges of the same MAV_CMD cannot be told
 * apart: those queue, while different commands run at once. [send] returns when the vehicle
 * accepted the command and throws [CommandRejected], [CommandTimeout] or
 * [pod.core.vehicle.VehicleLost] otherwise.
 */
public class CommandService internal constructor(
    private val vehicle: MavlinkVehicle,
    /** Timeouts of every command to this vehicle. */
    public var timing: CommandTiming = CommandTiming(),
) {
    private val locks = HashMap<Int, Mutex>()
    private var roundTrip: CommandRoundTrip? = null
    private var roundTripTiming: CommandTiming? = null

    /**
     * Sends [command] and suspends until the vehicle accepted it; reports IN_PROGRESS percentages
     * to [onProgress]. Returns the vehicle's reply (its `result_param2` means something for a few
     * commands).
     */
    public suspend fun send(command: VehicleCommand, onProgress: (Int?) -> Unit = {}): CommandReply =
        lockFor(command.command).withLock { exchange(command, onProgress) }

    private fun lockFor(command: Int): Mutex = synchronized(locks) { locks.getOrPut(command) { Mutex() } }

    private fun roundTrip(): CommandRoundTrip = synchronized(locks) {
        val current = timing
        if (roundTripTiming != current) {
            roundTrip = CommandRoundTrip(current)
            roundTripTiming = current
        }
        roundTrip!!
    }

    private suspend fun exchange(command: VehicleCommand, onProgress: (Int?) -> Unit): CommandReply {
        val clock = vehicle.clock.markNow()
        fun now() = clock.elapsedNow().inWholeNanoseconds
        val identity = vehicle.identity.value
        val ourSystem = vehicle.station.config.systemId
        val machine = CommandTransaction(command, timing, roundTrip())
        val texts = RefusalTexts()
        // When the vehicle's autopilot last sent anything, on this exchange's clock (set on the collector's thread).
        val lastHeard = AtomicLong(-vehicle.lastHeartbeat.elapsedNow().inWholeNanoseconds)
        return vehicle.exchange(command.label, pick = { inbound ->
            if (inbound.frame.componentId == identity.componentId) lastHeard.set(now())
            when (val message = inbound.message) {
                // Older autopilots leave the target empty (0); anything else must be us.
                is CommandAck -> if (inbound.frame.componentId == identity.componentId && message.targetSystem() in setOf(0, ourSystem)) {
                    CommandWire.reply(message)?.takeIf { it.command == command.command }
                } else null
                else -> null
            }
        }, giveUpAfter = timing.timeout) { replies, watch ->
            // Texts come from the vehicle's joined STATUSTEXT lines (a long one arrives in chunks).
            val listening = launch(start = CoroutineStart.UNDISPATCHED) {
                vehicle.statusTexts.collect { if (it.severity.ordinal <= MAV_SEVERITY_WARNING) texts.add(it.text) }
            }
            try {
                var step = machine.start(now())
                while (true) {
                    if (step.confirmation >= 0) {
                        vehicle.send(CommandWire.encode(command, identity.systemId, identity.componentId, step.confirmation))
                        watch.sent()
                    }
                    val outcome = step.outcome
                    if (outcome != null) {
                        if (outcome is CommandTransaction.Outcome.Rejected) texts.awaitQuiet()
                        machine.error(outcome, texts.lines())?.let { error ->
                            throw if (error is CommandRejected && error.statusTexts.isEmpty()) {
                                val t = vehicle.telemetry
                                error.withHint(RefusalHints.forRefusal(command, error.result, vehicle.identity.value, t.mode.value?.name, t.armed.value))
                            } else {
                                error
                            }
                        }
                        return@exchange (outcome as CommandTransaction.Outcome.Accepted).reply
                    }
                    val wait = (step.wakeAt - now()).coerceAtLeast(0)
                    step = select {
                        replies.onReceive { reply ->
                            machine.onReply(reply, now()).also { if (reply.result == CommandResult.IN_PROGRESS) onProgress(machine.progress) }
                        }
                        if (step.wakeAt != Long.MAX_VALUE) onTimeout(wait.nanoseconds) { machine.onTimer(now(), vehicleTalking = now() - lastHeard.get() < TALKING_WITHIN_NANOS) }
                    }
                }
                @Suppress("UNREACHABLE_CODE")
                error("unreachable")
            } finally {
                listening.cancel()
            }
        }
    }

    /**
     * The lines that explain a refusal: collected while the command is pending and for a moment
     * after the refusal, each line once however often the vehicle repeats it.
     */
    private class RefusalTexts {
        private val lines = LinkedHashSet<String>()
        private val arrived = Channel<Unit>(Channel.CONFLATED)

        fun add(line: String) {
            // PX4's commander ends the lines it also sends as events with a tab (Commander.cpp:
            // "Mission start denied! No valid mission\t"): with or without it, the same line.
            synchronized(lines) { lines += line.trim() }
            arrived.trySend(Unit)
        }

        fun lines(): List<String> = synchronized(lines) { lines.toList() }

        /**
         * ArduPilot answers COMMAND_ACK at once and sends the lines explaining it from its text
         * queue right after (GCS_Common.cpp: GCS_MAVLINK::handle_command_long sends the ack;
         * GCS::send_textv only queues the text, which GCS_MAVLINK::service_statustext sends on the
         * next update_send pass, the same millisecond on SITL). So after a refusal, keep listening
         * until the vehicle has been quiet for [QUIET_GAP] (several lines come back to back), at
         * most [AT_MOST]: long enough for a queued line behind the ack on a slow radio, short
         * enough that a refusal without any text is reported at once.
         */
        suspend fun awaitQuiet() {
            arrived.tryReceive() // what came before the refusal does not extend the wait
            kotlinx.coroutines.withTimeoutOrNull(AT_MOST) {
                while (kotlinx.coroutines.withTimeoutOrNull(QUIET_GAP) { arrived.receive() } != null) Unit
            }
        }

        private companion object {
            val QUIET_GAP = 150.milliseconds
            val AT_MOST = 500.milliseconds
        }
    }

    private companion object {
        /** Texts up to this severity explain a refusal; notices and info are chatter. */
        const val MAV_SEVERITY_WARNING = 4

        /**
         * A vehicle heard this recently is alive and the command or its ack was lost: resend
         * quickly. Heartbeats alone come once a second; a second is also what telemetry streams
         * at a few Hz leave between messages at 30 % loss only rarely.
         */
        val TALKING_WITHIN_NANOS = 1.seconds.inWholeNanoseconds
    }
}
