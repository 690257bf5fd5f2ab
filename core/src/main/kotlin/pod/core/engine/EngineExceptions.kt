package pod.core.engine

import pod.core.units.toReadable
import kotlin.time.Duration

/** A pick found too few vehicles within its timeout. */
public class PickTimeout(
    /** What was asked for. */
    public val request: PickRequest,
    /** How many free vehicles met it when time ran out. */
    public val matching: Int,
    /** How long it waited, in vehicle time. */
    public val waited: Duration,
) : pod.core.PodException("pick timed out after ${waited.toReadable()}: wanted ${request.describe()}, found $matching")

/** A task asked for a vehicle that another running task holds; a vehicle is in at most one running task. */
public class VehicleBusy(
    /** The vehicle's id. */
    public val vehicleId: Int,
    /** The task that wanted it. */
    public val wanted: String,
    /** The task that holds it. */
    public val heldBy: String,
) : pod.core.PodException("vehicle $vehicleId is busy with '$heldBy' and cannot run '$wanted'")

/** A mission task was run without vehicles: bind it with `on`. */
public class UnboundTask(
    /** The task's label. */
    public val task: String,
) : pod.core.PodException("task '$task' has no vehicles: bind it to a vehicle set with `on`")

/** The program tried to release vehicles it had not picked. */
public class NotPicked(
    /** The ids it had not picked. */
    public val vehicleIds: Set<Int>,
) : pod.core.PodException("vehicles $vehicleIds were not picked by this program")
