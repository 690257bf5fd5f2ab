// Dolphin's Listing 2 as a script: one drone surveys until its battery is below 80 %, then comes
// home and lands.
//
//   ./pod run samples/scripts/low-battery-survey.main.kts --sim 1 --time-scale 40
//
// `pod run` puts Pod on the classpath; run with plain `kotlin` after `./mvnw install`, the
// DependsOn lines below find it in ~/.m2 (and then it flies 4 simulated drones in real time).
@file:DependsOn("pod:pod-launch:0.1.0")
@file:DependsOn("pod:pod-dsl:0.1.0")

import pod.core.units.m
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.dsl.until
import pod.launch.pod

pod {
    val v = pick { count(1) }[0]
    val home = v.home.value!!
    val survey = mission("survey") {
        home(home)
        takeOff(30.m)
        moveFromHome(north = 40.m, up = 30.m)
        surveyArea(length = 300.m, width = 200.m, spacing = 25.m)
        returnHomeAndLand()
    }
    execute((survey on v) until { battery(v) < 0.8 })
    message("battery at ${(battery(v) * 100).toInt()} %: coming home")
    execute(mission("home") { home(home); goPos(home.latitude, home.longitude, 30.m); returnHomeAndLand() } on v)
    release(v)
    message("${v.name} landed at home")
}
