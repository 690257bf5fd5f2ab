package pod.mavlink.codec

import io.dronefleet.mavlink.MavlinkDialect
import io.dronefleet.mavlink.annotations.MavlinkMessageInfo

/** A message class known to the dialect, with its plan built on first use. */
internal class MessageType(val id: Int, val crcExtra: Int, val messageClass: Class<*>, enumTables: EnumValueTables) {
    /** Built lazily: most of the ~300 dialect messages never appear on a given link. */
    val plan: MessagePlan by lazy(LazyThreadSafetyMode.PUBLICATION) { MessagePlanner.plan(messageClass, enumTables) }
}

/**
 * The dialect's messages indexed by id and by class, built once. Ids sit in a sorted array searched
 * by bisection: MAVLink 2 ids go up to 2^24 and are sparse, and this keeps per-frame lookups free of
 * boxing and hashing.
 */
internal class MessageCatalog(dialect: MavlinkDialect) {
    private val ids: IntArray
    private val types: Array<MessageType>
    private val byClass: Map<Class<*>, MessageType>

    init {
        val enumTables = EnumValueTables()
        val byId = HashMap<Int, MessageType>()
        val classes = HashMap<Class<*>, MessageType>()
        // messageTypes() lists the dialect's own messages before its dependencies'; keeping the first
        // class per id matches how the dialect's resolve(id) breaks such ties.
        for (rawClass in dialect.messageTypes()) {
            val messageClass: Class<*> = rawClass // the dialect API returns raw Class, which hides getAnnotation's type
            val info = messageClass.getAnnotation(MavlinkMessageInfo::class.java) ?: continue
            val type = MessageType(info.id, info.crc, messageClass, enumTables)
            classes.putIfAbsent(messageClass, type)
            byId.putIfAbsent(info.id, type)
        }
        ids = byId.keys.sorted().toIntArray()
        types = Array(ids.size) { byId.getValue(ids[it]) }
        byClass = classes
    }

    /** The message with [id], or null. */
    fun byId(id: Int): MessageType? {
        val index = ids.binarySearch(id)
        return if (index >= 0) types[index] else null
    }

    /** The message whose class is [messageClass], or null. */
    fun byClass(messageClass: Class<*>): MessageType? = byClass[messageClass]

    /** Every message class of the dialect, one per id, by ascending id. */
    val messageClasses: List<Class<*>> get() = types.map { it.messageClass }
}
