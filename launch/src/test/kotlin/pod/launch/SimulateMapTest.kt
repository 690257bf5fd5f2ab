package pod.launch

import io.kotest.core.spec.style.StringSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.runTest
import pod.core.time.Timebase
import pod.core.units.m
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.launch.geo.GeoJson
import pod.launch.geo.GeoShape
import pod.launch.geo.MapFeatures
import pod.mavlink.link.MemoryNetwork
import pod.sim.LinkOpener
import pod.sim.SimFlavor
import java.io.File

class SimulateMapTest : StringSpec({
    "a program's map written as GeoJSON holds each vehicle's planned mission, flown track and home" {
        val out = File(tempdir(), "run.geojson")
        runTest {
            // Virtual time on an in-memory network: the subject is the map of a run, not sockets.
            val timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
            val network = MemoryNetwork(backgroundScope, timebase)
            val (home, record) = simulate(listOf(SimFlavor.ARDUCOPTER), timeScale = 1.0, map = out.toPath(), timebase = timebase, openLink = LinkOpener.memory(network)) {
                val v = pick { count(1) }[0]
                val home = v.home.value!!
                execute(mission("hop") { home(home); takeOff(10.m); move(north = 30.m); returnHomeAndLand() } on v)
                home
            }
            val features = GeoJson.read(out.readText())
            features.map { it.properties["kind"] } shouldBe listOf(MapFeatures.MISSION, MapFeatures.TRACK, MapFeatures.HOME)
            features.forEach { it.properties["vehicle"] shouldBe 1L }
            features[0].name shouldBe "hop"
            val track = (features[1].shape as GeoShape.Line).points
            track shouldBe record.tracks.getValue(1).second
            track.maxOf { it.distanceTo(home.copy(altitude = it.altitude)).meters } shouldBe (30.0 plusOrMinus 4.0) // thinned to 2 m, the waypoint reached within its 2 m radius
            (features[2].shape as GeoShape.Point).at.distanceTo(home).meters shouldBeLessThan 0.01
        }
    }
})
