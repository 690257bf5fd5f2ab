package pod.test

/** Checks on polygons given as (north, east) metres, written out here so the Arb's own construction is not what tests it. */
internal object Polygons {
    /** True when no two non-adjacent edges touch and no two adjacent edges overlap. */
    fun simple(p: List<Pair<Double, Double>>): Boolean {
        val n = p.size
        for (i in 0 until n) for (j in i + 1 until n) {
            val adjacent = j == i + 1 || (i == 0 && j == n - 1)
            if (!adjacent && crosses(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return false
        }
        return true
    }

    /** True when every turn along the boundary goes the same way. */
    fun convex(p: List<Pair<Double, Double>>): Boolean {
        val turns = p.indices.map { i -> cross(p[i], p[(i + 1) % p.size], p[(i + 2) % p.size]) }
        return turns.all { it > 0 } || turns.all { it < 0 }
    }

    private fun cross(o: Pair<Double, Double>, a: Pair<Double, Double>, b: Pair<Double, Double>): Double =
        (a.second - o.second) * (b.first - o.first) - (a.first - o.first) * (b.second - o.second)

    private fun crosses(a: Pair<Double, Double>, b: Pair<Double, Double>, c: Pair<Double, Double>, d: Pair<Double, Double>): Boolean {
        val d1 = cross(c, d, a)
        val d2 = cross(c, d, b)
        val d3 = cross(a, b, c)
        val d4 = cross(a, b, d)
        return (d1 * d2 <= 0) && (d3 * d4 <= 0)
    }
}
