// Runs under `pod run` as it is; with plain kotlin after `./mvnw install`.
@file:DependsOn("pod:pod-launch:0.1.0")

import pod.core.units.Location
import pod.launch.FleetChoice

val start = Location(41.1785, -8.5957)
val end = Location(41.1795, -8.5957)
println("distance: %.3f m".format(start.distanceTo(end).meters))
println("fleet: ${FleetChoice.fromSystemProperties()}")
println("dsl: ${pod.dsl.PodDsl::class.simpleName}")
println("args: ${args.joinToString(" ")}")
