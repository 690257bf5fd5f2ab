import pod.core.units.Location

println("before")
Location(91.0, 0.0)
println("never printed")
