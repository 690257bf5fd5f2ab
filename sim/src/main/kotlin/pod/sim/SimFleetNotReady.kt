package pod.sim

import pod.core.PodException
import kotlin.time.Duration

/**
 * A simulated fleet whose vehicles were not all ready within [timeout] of starting: [waiting]
 * maps the system id of each vehicle not ready to what the station had not heard from it yet
 * ("no heartbeat", "no position", "no 3D fix", "no home").
 */
public class SimFleetNotReady(
    /** How long [SimPlatform.start] waited. */
    public val timeout: Duration,
    /** System id → what was not heard from that vehicle. */
    public val waiting: Map<Int, String>,
) : PodException(
    "simulated fleet not ready after $timeout: " + waiting.entries.sortedBy { it.key }.joinToString { (id, what) -> "vehicle $id: $what" },
)
