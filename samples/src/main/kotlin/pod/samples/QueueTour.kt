package pod.samples

import kotlinx.coroutines.flow.first
import pod.core.engine.Program
import pod.core.platform.PlatformVehicle
import pod.core.queue.at
import pod.core.units.m
import pod.dsl.action
import pod.dsl.and
import pod.dsl.idle
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.dsl.queue.circle
import pod.dsl.queue.goto
import pod.dsl.queue.on
import pod.dsl.queue.path
import pod.dsl.queue.segment
import kotlin.time.Duration.Companion.seconds

/**
 * The mission queue (Paparazzi's mission interface) on one vehicle: it takes off and flies a queue
 * that an operator task feeds while it flies — three gotos appended, a circle prepended for a
 * minute, the current goto replaced by a segment, everything replaced by a path whose end is
 * skipped with `next()` — then lands at home. West of home, clear of Listing 4's survey areas.
 */
suspend fun Program.queueTour(): PlatformVehicle {
    val v = pick { count(1) }[0]
    message("queue: ${v.name} takes off and flies a queue that an operator feeds as it flies")
    execute(mission("take off ${v.name}") { home(homeOf(v)); takeOff(30.m) } on v)
    val queue = missionQueue()
    val operator = action("operator") {
        queue.append(goto(at(100.m, (-150).m)))
        val second = queue.append(goto(at(250.m, (-150).m)))
        queue.append(goto(at(250.m, (-300).m)))
        message("queue: appended three gotos")
        queue.state.first { it.current == second }
        val circle = queue.prepend(circle(at(175.m, (-225).m), (-40).m, duration = 60.seconds))
        message("queue: prepended a counter-clockwise circle for 60 s; the goto resumes after it")
        queue.state.first { it.current != circle }
        val segment = queue.replaceCurrent(segment(at(300.m, (-100).m), at(0.m, (-100).m)))
        message("queue: replaced the current goto with a segment")
        queue.state.first { it.current != segment }
        queue.replaceAll(path(at(0.m, (-50).m), at(100.m, (-150).m), at(200.m, (-50).m), at(300.m, (-150).m), at(200.m, (-250).m)))
        message("queue: replaced everything with a five-point path")
        execute(idle(70.seconds))
        queue.next()
        message("queue: next() skipped the rest of the path; ${v.name} holds, then lands at home")
    }
    execute((queue on v) and operator)
    execute(landAtHome(v) on v)
    release(v)
    return v
}
