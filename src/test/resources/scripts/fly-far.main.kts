// A long flight north, for stopping `pod run` while the vehicle flies it (InterruptSpec).
@file:DependsOn("pod:pod-launch:0.1.0")
@file:DependsOn("pod:pod-dsl:0.1.0")

import kotlinx.coroutines.flow.first
import pod.core.units.*
import pod.dsl.*
import pod.launch.pod

pod {
    val v = pick { count(1) }[0]
    val home = v.home.first { it != null }!!
    execute(mission("far") { home(home); takeOff(30.m); move(north = 2.km); returnHomeAndLand() } on v)
}
