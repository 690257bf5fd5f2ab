package pod.mavlink.codec

/**
 * The little JSON the vector file needs (objects, arrays, strings, numbers), so the tests carry no
 * JSON library. Numbers stay as their text ([Number]) so each field converts them exactly to its type.
 */
internal class MiniJson private constructor(private val text: String) {
    /** A JSON number, exactly as written. */
    data class Number(val text: String)

    private var at = 0

    companion object {
        /** The value [text] holds: Map, List, String, [Number], Boolean or null. */
        fun parse(text: String): Any? = MiniJson(text).run {
            val value = value()
            space()
            require(at == text.length) { "trailing text at $at" }
            value
        }
    }

    private fun value(): Any? {
        space()
        return when (val c = text[at]) {
            '{' -> obj()
            '[' -> array()
            '"' -> string()
            't' -> literal("true", true)
            'f' -> literal("false", false)
            'n' -> literal("null", null)
            else -> if (c == '-' || c.isDigit()) number() else error("unexpected '$c' at $at")
        }
    }

    private fun obj(): Map<String, Any?> {
        val map = LinkedHashMap<String, Any?>()
        at++
        space()
        if (text[at] == '}') return map.also { at++ }
        while (true) {
            space()
            val key = string()
            space()
            expect(':')
            map[key] = value()
            space()
            if (text[at++] == '}') return map
        }
    }

    private fun array(): List<Any?> {
        val list = ArrayList<Any?>()
        at++
        space()
        if (text[at] == ']') return list.also { at++ }
        while (true) {
            list += value()
            space()
            if (text[at++] == ']') return list
        }
    }

    private fun string(): String {
        expect('"')
        val out = StringBuilder()
        while (true) {
            when (val c = text[at++]) {
                '"' -> return out.toString()
                '\\' -> when (val e = text[at++]) {
                    'n' -> out.append('\n')
                    't' -> out.append('\t')
                    'r' -> out.append('\r')
                    'b' -> out.append('\b')
                    'f' -> out.append('\u000C')
                    'u' -> out.append(text.substring(at, at + 4).toInt(16).toChar()).also { at += 4 }
                    else -> out.append(e)
                }
                else -> out.append(c)
            }
        }
    }

    private fun number(): Number {
        val start = at
        while (at < text.length && text[at] in "+-0123456789.eE") at++
        return Number(text.substring(start, at))
    }

    private fun literal(word: String, value: Any?): Any? {
        require(text.startsWith(word, at)) { "bad literal at $at" }
        at += word.length
        return value
    }

    private fun expect(c: Char) {
        require(text[at] == c) { "expected '$c' at $at" }
        at++
    }

    private fun space() {
        while (at < text.length && text[at].isWhitespace()) at++
    }
}
