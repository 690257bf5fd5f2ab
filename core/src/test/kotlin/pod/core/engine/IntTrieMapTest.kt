package pod.core.engine

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.choice
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.pair
import io.kotest.property.checkAll

class IntTrieMapTest : FunSpec({
    test("puts and removes of any keys, small, large and negative, behave as an ordinary map, and old versions stay as they were") {
        val keys = Arb.choice(Arb.int(0..40), Arb.int(0..5000), Arb.int())
        checkAll(PropTestConfig(seed = 20261122, iterations = 200), Arb.list(Arb.pair(Arb.boolean(), keys), 0..150)) { ops ->
            var trie = IntTrieMap.empty<String>()
            val model = mutableMapOf<Int, String>()
            val versions = mutableListOf<Pair<IntTrieMap<String>, Map<Int, String>>>()
            for ((put, key) in ops) {
                if (put) {
                    trie = trie.put(key, "v$key-${model.size}")
                    model[key] = "v$key-${model.size}"
                } else {
                    trie = trie.remove(key)
                    model.remove(key)
                }
                versions += trie to model.toMap()
            }
            for ((version, expected) in versions) {
                version shouldBe expected
                version.size shouldBe expected.size
                version.keys.sortedBy { it.toUInt() } shouldBe version.keys.toList()
                expected.keys.forEach { version[it] shouldBe expected[it] }
            }
        }
    }
})
