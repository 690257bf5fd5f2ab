import pod.core.units.Location

val here = Location(41.1785, -8.5957)
println("at $here"
