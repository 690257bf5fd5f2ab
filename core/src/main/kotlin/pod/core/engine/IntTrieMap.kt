package pod.core.engine

/**
 * An immutable map from Int keys that shares structure between versions: [put] and [remove] copy
 * the few small nodes on the key's path (two for keys below 1024), not the whole map. The engine keeps its vehicle claims in
 * one, so that claiming a vehicle costs the same with 10 vehicles busy as with 10,000 (copying a
 * hash map per claim made a program of n concurrent missions cost O(n²)). Iterates in unsigned key
 * order.
 */
internal class IntTrieMap<V : Any> private constructor(
    /** A 32-way trie over the low [levels] × 5 bits of the key, most significant first; the last level holds the values. */
    private val root: Array<Any?>?,
    private val levels: Int,
    override val size: Int,
) : AbstractMap<Int, V>() {
    override fun get(key: Int): V? {
        if (levelsFor(key) > levels) return null
        var node = root ?: return null
        for (level in 0 until levels - 1) node = child(node, key, level) ?: return null
        @Suppress("UNCHECKED_CAST")
        return node[slot(key, levels - 1)] as V?
    }

    override fun containsKey(key: Int): Boolean = get(key) != null

    /** This map with [key] mapped to [value]. */
    fun put(key: Int, value: V): IntTrieMap<V> {
        val had = containsKey(key)
        // A key too large for this trie: the current trie becomes the first child of a taller one.
        var grown = root
        var height = levels
        while (height < levelsFor(key)) {
            grown = grown?.let { arrayOfNulls<Any?>(WIDTH).also { top -> top[0] = it } }
            height++
        }
        return IntTrieMap(put(grown, key, value, 0, height), height, if (had) size else size + 1)
    }

    /** This map without [key] (itself when the key is absent). */
    fun remove(key: Int): IntTrieMap<V> = if (!containsKey(key)) this else IntTrieMap(remove(root!!, key, 0, levels), levels, size - 1)

    override val entries: Set<Map.Entry<Int, V>>
        get() = object : AbstractSet<Map.Entry<Int, V>>() {
            override val size: Int get() = this@IntTrieMap.size
            override fun iterator(): Iterator<Map.Entry<Int, V>> = iterator { root?.let { yieldAll(it, 0, 0) } }
        }

    private suspend fun SequenceScope<Map.Entry<Int, V>>.yieldAll(node: Array<Any?>, level: Int, prefix: Int) {
        for (i in 0 until WIDTH) {
            val item = node[i] ?: continue
            val key = (prefix shl BITS) or i
            @Suppress("UNCHECKED_CAST")
            if (level == levels - 1) yield(Entry(key, item as V)) else yieldAll(item as Array<Any?>, level + 1, key)
        }
    }

    private fun slot(key: Int, level: Int): Int = slot(key, level, levels)

    private fun child(node: Array<Any?>, key: Int, level: Int): Array<Any?>? = child(node, key, level, levels)

    private class Entry<V>(override val key: Int, override val value: V) : Map.Entry<Int, V> {
        override fun equals(other: Any?): Boolean = other is Map.Entry<*, *> && other.key == key && other.value == value

        override fun hashCode(): Int = key.hashCode() xor value.hashCode()

        override fun toString(): String = "$key=$value"
    }

    companion object {
        private const val BITS = 5
        private const val WIDTH = 1 shl BITS

        /** 7 × 5 bits cover all 32 bits of a key. */
        private const val MAX_LEVELS = 7

        private val EMPTY = IntTrieMap<Any>(null, 1, 0)

        /** The empty map. */
        @Suppress("UNCHECKED_CAST")
        fun <V : Any> empty(): IntTrieMap<V> = EMPTY as IntTrieMap<V>

        /** How many levels a trie needs to hold [key]: 1 below 32, 2 below 1024, …, 7 for negative keys. */
        private fun levelsFor(key: Int): Int {
            var levels = 1
            while (levels < MAX_LEVELS && (key ushr (levels * BITS)) != 0) levels++
            return levels
        }

        private fun slot(key: Int, level: Int, levels: Int): Int = (key ushr ((levels - 1 - level) * BITS)) and (WIDTH - 1)

        @Suppress("UNCHECKED_CAST")
        private fun child(node: Array<Any?>, key: Int, level: Int, levels: Int): Array<Any?>? = node[slot(key, level, levels)] as Array<Any?>?

        private fun put(node: Array<Any?>?, key: Int, value: Any, level: Int, levels: Int): Array<Any?> {
            val copy = node?.copyOf() ?: arrayOfNulls(WIDTH)
            val i = slot(key, level, levels)
            copy[i] = if (level == levels - 1) value else put(node?.let { child(it, key, level, levels) }, key, value, level + 1, levels)
            return copy
        }

        /** [node] without [key], or null when nothing is left in it; the key is present. */
        private fun remove(node: Array<Any?>, key: Int, level: Int, levels: Int): Array<Any?>? {
            val i = slot(key, level, levels)
            val replacement = if (level == levels - 1) null else remove(child(node, key, level, levels)!!, key, level + 1, levels)
            if (replacement == null && node.indices.all { it == i || node[it] == null }) return null
            return node.copyOf().also { it[i] = replacement }
        }
    }
}
