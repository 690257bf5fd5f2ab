// The README's "Programs" example as a script: the program block is the README's, unchanged.
@file:DependsOn("pod:pod-cli:0.1.0-SNAPSHOT")

import pod.core.platform.PlatformVehicle
import pod.core.units.*
import pod.dsl.*
import pod.launch.pod
import kotlin.time.Duration.Companion.seconds

pod {
        val (a, b) = pick { count(2); payload("camera"); region(location(41.178, -8.596) radius 2.km); timeout(30.seconds) }.members
        val survey = { v: PlatformVehicle, east: Distance -> mission("survey ${v.name}") {
            home(v.home.value!!); takeOff(30.m); moveFromHome(north = 40.m, east = east, up = 30.m)
            surveyArea(length = 600.m, width = 300.m, spacing = 20.m); returnHomeAndLand()
        } }
        execute(((survey(a, 0.m) on a) and (survey(b, 150.m) on b)) until { battery(a) < 0.3 || battery(b) < 0.3 })
        execute(mission("home") { home(a.home.value!!); returnHome() } on (a + b))
        release(a + b)
}
