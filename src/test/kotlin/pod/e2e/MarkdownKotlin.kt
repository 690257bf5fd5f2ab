package pod.e2e

import java.io.File

/**
 * A ```kotlin block of a Markdown file as a `.main.kts` script: [prefix] (the context a
 * `<!-- fragment … -->` comment right above the block gives: imports, an enclosing function) then
 * the block's [code], then the braces [prefix] left open. [skipped] is the reason a
 * `<!-- not compiled: … -->` comment gives for a block that is not Kotlin against Pod (a Gradle
 * build script).
 */
internal class KotlinBlock(val file: String, val line: Int, val prefix: List<String>, val code: List<String>, val skipped: String?) {
    /** Where the block starts, as `README.md:37`. */
    val where: String get() = "$file:$line"

    /** The script to compile. */
    val script: String
        get() {
            val open = prefix.sumOf { l -> l.count { it == '{' } - l.count { it == '}' } }
            return (prefix + code + List(open) { "}" }).joinToString("\n", postfix = "\n")
        }

    /** The script with its line numbers, for a failure message. */
    val numbered: String get() = script.lines().mapIndexed { i, l -> "%3d  %s".format(i + 1, l) }.joinToString("\n")
}

/** Reads the ```kotlin blocks of Markdown files. */
internal object MarkdownKotlin {
    private val notCompiled = Regex("""<!--\s*not compiled:\s*(.+?)\s*-->""")

    /** Every ```kotlin block of [markdown], named by [name] in messages. */
    fun blocks(markdown: File, name: String = markdown.name): List<KotlinBlock> {
        val lines = markdown.readLines()
        val blocks = ArrayList<KotlinBlock>()
        var i = 0
        while (i < lines.size) {
            if (lines[i].trim() != "```kotlin") {
                i++
                continue
            }
            val end = (i + 1 until lines.size).firstOrNull { lines[it].trim() == "```" }
                ?: error("$name:${i + 1}: a ```kotlin block that is never closed")
            val above = lines.getOrNull(i - 1)?.trim().orEmpty()
            val skipped = notCompiled.matchEntire(above)?.groupValues?.get(1)
            val prefix = if (above == "-->") fragmentAbove(lines, i - 1, name) else emptyList()
            blocks += KotlinBlock(name, i + 1, prefix, lines.subList(i + 1, end), skipped)
            i = end + 1
        }
        return blocks
    }

    /** The Kotlin lines of the `<!-- fragment` comment that ends on line [closing] (0-based). */
    private fun fragmentAbove(lines: List<String>, closing: Int, name: String): List<String> {
        val start = (closing - 1 downTo 0).firstOrNull { lines[it].trim().startsWith("<!--") }
            ?: error("$name:${closing + 1}: a comment end with no start")
        check(lines[start].trim() == "<!-- fragment") {
            "$name:${start + 1}: the comment above a ```kotlin block must be `<!-- fragment` (its context) or `<!-- not compiled: why -->`"
        }
        return lines.subList(start + 1, closing)
    }
}
