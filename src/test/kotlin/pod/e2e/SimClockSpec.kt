package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.comparables.shouldBeLessThan
import io.kotest.matchers.shouldNotBe
import pod.core.engine.EngineEvent
import pod.core.platform.MissionEvent
import pod.core.units.m
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.launch.simulate
import pod.sim.SimFlavor
import pod.sim.SimPlatform
import java.util.concurrent.ConcurrentHashMap
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * A simulated vehicle's confirmations cost seconds of its own time: its heartbeat and streams
 * follow its clock, so the ground station's waits for the next heartbeat (mode, armed) and the
 * next MISSION_CURRENT do not turn into simulated minutes at a high time scale (`pod demo` at 40x
 * once showed "mission on board 00:06", "started 01:54").
 */
class SimClockSpec : StringSpec({
    for (flavor in listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4)) {
        "a $flavor at 40x goes from mission on board to started in seconds of its own time" {
            // On the virtual clock at 40x: the time scale is the subject, not the sockets.
            virtualRun {
                val clockAt = ConcurrentHashMap<String, Duration>()
                var fleet: SimPlatform? = null
                simulate(listOf(flavor), timeScale = 40.0, timebase = timebase, openLink = openLink, onEvent = { event ->
                    val sim = fleet?.get(1)
                    if (sim != null && event is EngineEvent.Mission) {
                        when (event.event) {
                            is MissionEvent.Uploaded -> clockAt["on board"] = sim.clock
                            MissionEvent.Started -> clockAt["started"] = sim.clock
                            else -> Unit
                        }
                    }
                }) { platform ->
                    fleet = platform
                    val v = pick { count(1) }[0]
                    execute(mission("hop") { home(v.home.value!!); takeOff(10.m); move(north = 20.m); returnHomeAndLand() } on v)
                }
                val onBoard = clockAt["on board"]
                val started = clockAt["started"]
                withClue("vehicle clock at: $clockAt") {
                    onBoard shouldNotBe null
                    started shouldNotBe null
                    // Before: ~92 s at 40x (about 2.3 s of wall time spent waiting for 1 Hz wall-clock heartbeats).
                    (started!! - onBoard!!) shouldBeLessThan 10.seconds
                }
            }
        }
    }
})
