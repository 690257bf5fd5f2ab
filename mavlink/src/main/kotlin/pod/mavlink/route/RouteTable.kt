package pod.mavlink.route

/**
 * Which (system, component) ids were heard on which endpoint, and where a frame goes from there: a
 * pure table with no I/O and no clock, one per router, used under the router's lock.
 *
 * The rules are mavlink-router's (mavlink-router/mavlink-router: `Endpoint::handle_read` learns the
 * sender of every frame read on an endpoint; `Mainloop::route_msg` offers it to every endpoint;
 * `Endpoint::accept_msg` in src/mavlink-router/endpoint.cpp decides):
 * 1. never to the endpoint it came from, nor to one where its sender was heard (a loop back);
 * 2. target system 0, or a message with no target field: every other endpoint (a broadcast);
 * 3. target component above 0: endpoints where that (system, component) was heard;
 *    target component 0 or none: endpoints where any component of that system was heard;
 * 4. a target heard nowhere else: nowhere, and [destinations] says so (mavlink-router counts it as
 *    `msg_to_unknown` and drops it).
 *
 * Memory is bounded: at most [maxIdsPerEndpoint] ids per endpoint (the oldest learnt is forgotten
 * first); the router bounds the number of endpoints.
 */
internal class RouteTable<E : Any>(private val maxIdsPerEndpoint: Int = DEFAULT_MAX_IDS) {
    init {
        require(maxIdsPerEndpoint >= 1) { "maxIdsPerEndpoint must be ≥ 1, was $maxIdsPerEndpoint" }
    }

    private val heard = LinkedHashMap<E, LinkedHashSet<Int>>()

    /** Endpoints known now, in the order they were added. */
    val endpoints: Set<E> get() = heard.keys

    /** Adds [endpoint] with nothing heard on it yet (a remote a link sends to before it answers). */
    fun add(endpoint: E) {
        heard.getOrPut(endpoint) { LinkedHashSet() }
    }

    /** Forgets [endpoint] and every id heard on it. */
    fun remove(endpoint: E) {
        heard.remove(endpoint)
    }

    /** Records that ([systemId], [componentId]) was heard on [endpoint] (added if new). */
    fun learn(endpoint: E, systemId: Int, componentId: Int) {
        val ids = heard.getOrPut(endpoint) { LinkedHashSet() }
        val id = key(systemId, componentId)
        if (id in ids) return
        if (ids.size >= maxIdsPerEndpoint) ids.remove(ids.first())
        ids += id
    }

    /** The ids heard on [endpoint] as (system shl 8) or component. */
    fun idsOf(endpoint: E): Set<Int> = heard[endpoint].orEmpty()

    /**
     * Adds to [into] every endpoint a frame from ([systemId], [componentId]) heard on [source] goes
     * to, for target [targetSystem] and [targetComponent] ([FrameTargets.NONE] when the message has
     * no such field). Returns false when the frame has a target system that no endpoint but its
     * own side has heard (rule 4): it goes nowhere.
     */
    fun destinations(source: E, systemId: Int, componentId: Int, targetSystem: Int, targetComponent: Int, into: MutableList<E>): Boolean {
        val sender = key(systemId, componentId)
        val broadcast = targetSystem == 0 || targetSystem == FrameTargets.NONE
        var found = false
        for ((endpoint, ids) in heard) {
            if (endpoint == source || sender in ids) continue
            val accepts = when {
                broadcast -> true
                targetComponent > 0 -> key(targetSystem, targetComponent) in ids
                else -> ids.any { it ushr 8 == targetSystem }
            }
            if (accepts) {
                into += endpoint
                found = true
            }
        }
        return found || broadcast
    }

    companion object {
        /** Ids one endpoint remembers: a ground station or a vehicle has a handful of components. */
        const val DEFAULT_MAX_IDS: Int = 64

        fun key(systemId: Int, componentId: Int): Int = (systemId shl 8) or componentId
    }
}
