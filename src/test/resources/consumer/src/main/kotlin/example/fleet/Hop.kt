package example.fleet

import kotlinx.coroutines.runBlocking
import pod.core.units.m
import pod.dsl.*
import pod.launch.simulate
import pod.sim.SimFlavor

/**
 * A user's program: one of two simulated copters takes off, flies 50 m north and comes home to land,
 * on Pod's simulator (`simulate`) at 50 times real time.
 */
fun main() {
    val (name, record) = runBlocking {
        simulate(List(2) { SimFlavor.ARDUCOPTER }, timeScale = 50.0, onLine = ::println) {
            val v = pick { count(1) }[0]
            execute(hop(v.home.value!!) on v)
            release(v)
            v.name
        }
    }
    println("fleet: $name flew ${record.flights.size} mission(s) on simulate")
}

/** Take off to 20 m, 50 m north, back home and land. */
fun hop(home: pod.core.units.Location) = mission("hop") {
    home(home)
    takeOff(20.m)
    move(north = 50.m)
    returnHomeAndLand()
}
