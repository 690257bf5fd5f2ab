package pod.core.survey

/** One photographed pass: along the scan line v = [v] of [strip], over [extent] in u. */
internal data class Pass(val strip: Int, val v: Double, val extent: Interval)

/** A pass in flying order: from its high-u end to its low-u end when [fromHigh]. */
internal data class FlownPass(val pass: Pass, val fromHigh: Boolean)

/**
 * Groups passes into cells that can each be flown back and forth without leaving them: a pass
 * continues the cell of the pass below it when each is the other's only overlapping neighbour;
 * wherever the region splits (a concave notch opens) or joins, new cells start. This is the
 * boustrophedon cell decomposition, read off the passes instead of computed from the polygon's
 * vertices; [passes] are grouped by strip, strips in order, each strip's passes sorted by u.
 */
internal fun cells(passes: List<List<Pass>>): List<List<Pass>> {
    val cells = ArrayList<MutableList<Pass>>()
    val cellOf = HashMap<Pass, MutableList<Pass>>()
    for (strip in passes.indices) {
        for (pass in passes[strip]) {
            val below = passes.getOrNull(strip - 1).orEmpty().filter { it.extent.overlaps(pass.extent) }
            val joins = below.singleOrNull()?.takeIf { under ->
                passes[strip].count { it.extent.overlaps(under.extent) } == 1
            }
            val cell = joins?.let(cellOf::getValue) ?: ArrayList<Pass>().also(cells::add)
            cell += pass
            cellOf[pass] = cell
        }
    }
    return cells
}

/** The four ways into a cell: from its first or last pass, at either end. */
internal fun entries(cell: List<Pass>): List<List<FlownPass>> =
    listOf(cell, cell.asReversed()).flatMap { ordered ->
        listOf(false, true).map { firstFromHigh ->
            ordered.mapIndexed { index, pass -> FlownPass(pass, firstFromHigh xor (index % 2 == 1)) }
        }
    }

/**
 * Orders the cells and the passes in them: first the cell entry nearest [start] (the turnaround
 * point before the first pass), then, greedily, the entry of an unflown cell nearest to where the
 * previous cell ended. [entryPoint] and [exitPoint] give where a flown pass begins and ends.
 */
internal fun flightOrder(
    cells: List<List<Pass>>,
    start: Point,
    entryPoint: (FlownPass) -> Point,
    exitPoint: (FlownPass) -> Point,
): List<FlownPass> {
    val remaining = cells.toMutableList()
    val order = ArrayList<FlownPass>()
    var here = start
    while (remaining.isNotEmpty()) {
        val (cell, route) = remaining
            .flatMap { cell -> entries(cell).map { cell to it } }
            .minBy { (_, route) -> entryPoint(route.first()).distanceTo(here) }
        remaining.remove(cell)
        order += route
        here = exitPoint(route.last())
    }
    return order
}
