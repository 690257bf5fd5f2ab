package pod.mavlink.plan

import pod.mavlink.command.VehicleCommand
import pod.mavlink.mission.MissionItem

/**
 * A [pod.core.mission.Mission] made ready for one [flavor] of autopilot: the [items] to upload, the
 * [keyedCommands] to send as commands when the vehicle reaches a point of the mission (steps the
 * flavour does not accept as mission items), and the [beforeStart] commands to send before the
 * vehicle is started (DO_SET_HOME for a mission that names its home).
 *
 * Every item but ArduPilot's home (item 0) belongs to one mission step: [stepOfItem] maps an
 * item's seq to the index of its step in `Mission.steps`.
 */
public data class MissionPlan(
    /** The autopilot family it was made for. */
    public val flavor: MissionFlavor,
    /** The mission items, numbered from 0 without gaps. */
    public val items: List<MissionItem>,
    /** Item seq → index of the mission step it belongs to (ArduPilot's home item has none). */
    public val stepOfItem: Map<Int, Int>,
    /** Steps sent as commands, each when the vehicle's current item reaches its [KeyedCommand.seq]. */
    public val keyedCommands: List<KeyedCommand>,
    /** Commands to send once the items are on board, before the vehicle is armed and started. */
    public val beforeStart: List<VehicleCommand>,
    /** How many steps the mission has. */
    public val stepCount: Int,
) {
    init {
        items.forEachIndexed { i, item -> require(item.seq == i) { "item $i has seq ${item.seq}; items must be numbered from 0 without gaps" } }
        require(stepOfItem.values.all { it in 0 until stepCount }) { "every mapped step must be in 0 until $stepCount" }
        require(keyedCommands.all { it.step in 0 until stepCount && it.seq in 0..items.size }) { "keyed commands must name a step and a seq in 0..${items.size}" }
    }

    /** The seqs of the items of [step], in order (empty for a step sent as a command). */
    public fun itemsOf(step: Int): List<Int> = stepOfItem.filterValues { it == step }.keys.sorted()

    /** The index of the step that item [seq] belongs to, or null (ArduPilot's home, or out of range). */
    public fun stepOf(seq: Int): Int? = stepOfItem[seq]

    /** The commands sent for [step] (empty when the step travels as items). */
    public fun commandsOf(step: Int): List<KeyedCommand> = keyedCommands.filter { it.step == step }
}

/**
 * Mission step [step] sent as [command] when the vehicle's current mission item reaches [seq] (the
 * item that follows the step), or when the last item is done for [seq] equal to the item count.
 */
public data class KeyedCommand(
    /** The item whose start triggers the command; the item count means "after the last item". */
    public val seq: Int,
    /** The mission step it carries out. */
    public val step: Int,
    /** What to send. */
    public val command: VehicleCommand,
)
