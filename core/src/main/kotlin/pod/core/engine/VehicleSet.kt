package pod.core.engine

import pod.core.platform.PlatformVehicle

/**
 * An ordered set of vehicles, as `pick` returns them; equal members are those with equal ids.
 * Supports Dolphin's set algebra: `a + b`, `a - b`, `a intersect b`.
 */
public class VehicleSet(vehicles: Iterable<PlatformVehicle>) : Iterable<PlatformVehicle> {
    /** The members in order, without duplicates. */
    public val members: List<PlatformVehicle> = vehicles.distinctBy { it.id }

    /** How many vehicles. */
    public val size: Int get() = members.size

    /** The ids of the members. */
    public val ids: Set<Int> get() = members.mapTo(LinkedHashSet()) { it.id }

    /** True when there is no vehicle. */
    public fun isEmpty(): Boolean = members.isEmpty()

    /** The [index]th member. */
    public operator fun get(index: Int): PlatformVehicle = members[index]

    /** True when [vehicle] is a member. */
    public operator fun contains(vehicle: PlatformVehicle): Boolean = members.any { it.id == vehicle.id }

    /** Members of either set. */
    public operator fun plus(other: Iterable<PlatformVehicle>): VehicleSet = VehicleSet(members + other)

    /** This set with [vehicle] added. */
    public operator fun plus(vehicle: PlatformVehicle): VehicleSet = VehicleSet(members + vehicle)

    /** Members of this set that are not in [other]. */
    public operator fun minus(other: Iterable<PlatformVehicle>): VehicleSet {
        val drop = other.mapTo(HashSet()) { it.id }
        return VehicleSet(members.filter { it.id !in drop })
    }

    /** This set without [vehicle]. */
    public operator fun minus(vehicle: PlatformVehicle): VehicleSet = VehicleSet(members.filter { it.id != vehicle.id })

    /** Members of both sets. */
    public infix fun intersect(other: Iterable<PlatformVehicle>): VehicleSet {
        val keep = other.mapTo(HashSet()) { it.id }
        return VehicleSet(members.filter { it.id in keep })
    }

    override fun iterator(): Iterator<PlatformVehicle> = members.iterator()

    override fun equals(other: Any?): Boolean = other is VehicleSet && other.ids == ids

    override fun hashCode(): Int = ids.hashCode()

    override fun toString(): String = members.joinToString(prefix = "[", postfix = "]") { it.name }

    /** Ready-made sets. */
    public companion object {
        /** No vehicle. */
        public val EMPTY: VehicleSet = VehicleSet(emptyList())
    }
}

/** The set holding just this vehicle. */
public fun PlatformVehicle.asSet(): VehicleSet = VehicleSet(listOf(this))
