package pod.e2e

/**
 * A module's Dokka includes file (`src/main/docs/packages.md`): a `# Module pod-x` section, then a
 * `# Package pod.x.y` section per package. Dokka shows each section's text as that module's or
 * package's overview page.
 */
object PackageOverviews {
    private val heading = Regex("""^#\s+(Module|Package)\s+(\S+)\s*$""")

    /** The sections of [markdown] by heading (`Module pod-core`, `Package pod.core.units`) with their text. */
    fun sections(markdown: String): Map<String, String> {
        val sections = LinkedHashMap<String, StringBuilder>()
        var current: StringBuilder? = null
        for (line in markdown.lines()) {
            val match = heading.matchEntire(line)
            if (match != null) {
                current = StringBuilder()
                sections["${match.groupValues[1]} ${match.groupValues[2]}"] = current
            } else {
                current?.appendLine(line)
            }
        }
        return sections.mapValues { it.value.toString().trim() }
    }

    /**
     * What is wrong with [markdown] as the includes file of [module] whose public API is in
     * [packages]: a missing or empty module section, a package without an overview, an overview
     * with no text, an overview of a package that has no public API (stale, or misspelled).
     */
    fun problems(module: String, markdown: String, packages: Set<String>): List<String> {
        val sections = sections(markdown)
        val problems = ArrayList<String>()
        if (sections["Module $module"].isNullOrBlank()) problems += "$module: no `# Module $module` overview"
        for (name in packages.sorted()) {
            val text = sections["Package $name"]
            if (text == null) problems += "$module: no `# Package $name` overview"
            else if (text.isBlank()) problems += "$module: the overview of $name is empty"
        }
        sections.keys.filter { it.startsWith("Package ") && it.removePrefix("Package ") !in packages }
            .forEach { problems += "$module: `# $it` names no package with public API" }
        return problems
    }
}
