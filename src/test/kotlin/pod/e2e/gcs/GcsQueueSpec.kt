package pod.e2e.gcs

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import pod.cli.json.PageAction
import pod.core.units.m
import kotlin.time.Duration.Companion.seconds

/**
 * The mission-queue panel in a real browser, against a simulated ArduCopter on loopback UDP: what
 * is drawn on the map is added to the vehicle's queue, flown (read from the SimVehicle's own
 * state), and the queue's status on the page follows.
 */
class GcsQueueSpec : StringSpec({

    "a circle dragged on the map is flown at its radius, a goto waits behind it, and next moves on to it" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            browser.open(gcs.url)
            browser.selectVehicle(1)
            // On the ground, nothing is added: the page says to take off first.
            browser.find("#queue-panel button[data-queue-tool='goto']").click()
            browser.clickMap(gcs.sim[1].offset(north = 20.0, east = 0.0))
            val refused = browser.await("the queue's answer") { browser.textOf("#queue-panel [data-answer='queue']").takeIf { it.startsWith("refused") } }
            refused shouldContain "take off first"

            val vehicle = gcs.fleet.vehicle(1)
            vehicle.action.arm()
            vehicle.action.takeoff(15.m)
            val centre = gcs.sim[1].offset(north = 0.0, east = 60.0)
            val dragged = 25.0
            browser.find("#queue-panel button[data-queue-tool='circle']").click()
            // The centre and the end of the drag on screen, as an operator zooms to where they draw.
            browser.fitMap(listOf(centre, centre.offset(0.m, (2 * dragged).m)))
            browser.dragOnMap(centre, pixels = (dragged * browser.pixelsPerMetre()).toInt())
            browser.await("the circle current on the page") { browser.textOf("#queue-panel .queue-status .current").takeIf { "circle" in it } }
            // The radius as dragged, to the pixel (whole metres: the page rounds it).
            val shown = Regex("r (\\d+) m clockwise").find(browser.textOf("#queue-panel .queue-status .current"))
            val radius = shown!!.groupValues[1].toDouble()
            radius shouldBe (dragged plusOrMinus 1.0)

            val afterwards = gcs.sim[1].offset(north = -40.0, east = 0.0)
            browser.find("#queue-panel button[data-queue-tool='goto']").click()
            browser.clickMap(afterwards)
            browser.awaitTrue("the goto pending on the page") { browser.findAll("#queue-panel .queue-status .pending li").size == 1 }
            browser.textOf("#queue-panel .queue-status .pending li") shouldContain "goto"
            browser.awaitTrue("the map drawing the circle and the pending goto") {
                browser.findAll("#map .queue .element.circle.current").size == 1 && browser.findAll("#map .queue .element.point.pending").size == 1
            }

            // Flown: on the circle, and still on it a while later (a quarter turn at 5 m/s is ~8 s of vehicle time).
            browser.awaitTrue("the sim on the circle", 60.seconds) { kotlin.math.abs(gcs.sim[1].distanceTo(centre) - radius) < 3 }
            val onCircle = gcs.sim[1].here
            browser.awaitTrue("the sim gone round the circle by 20 m", 60.seconds) { gcs.sim[1].distanceTo(onCircle) > 20 }
            gcs.sim[1].distanceTo(centre) shouldBe (radius plusOrMinus 3.0)
            gcs.sim[1].height shouldBe (15.0 plusOrMinus 1.5)
            browser.find("#queue-panel [data-queue-flight]").getAttribute("data-queue-flight") shouldBe "flying"
            browser.screenshot("queue-circle")

            browser.find("#queue-panel button[data-queue='next']").click()
            browser.await("next's answer") { browser.textOf("#queue-panel [data-answer='queue']").takeIf { it.startsWith("ok") && "circle" in it } }
            browser.awaitTrue("the goto current on the page") { browser.textOf("#queue-panel .queue-status .current").contains("goto") }
            browser.findAll("#queue-panel .queue-status .pending li").size shouldBe 0
            browser.awaitTrue("the sim at the goto", 60.seconds) { gcs.sim[1].distanceTo(afterwards) < 3 }
            browser.awaitTrue("the queue empty on the page once the goto is reached") { browser.textOf("#queue-panel .queue-status .current").contains("nothing") }
            browser.screenshot("queue-next")
        }
    }

    "a path of clicked points is flown point by point; clear empties the queue and the vehicle holds" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            gcs.flyingOnPage(browser, height = 10.0)
            val points = listOf(gcs.sim[1].offset(30.0, 0.0), gcs.sim[1].offset(30.0, 30.0))
            browser.find("#queue-panel button[data-queue-tool='path']").click()
            points.forEach { browser.clickMap(it) }
            browser.find("#queue-panel button[data-queue='finish']").click()
            browser.await("the path's answer") { browser.textOf("#queue-panel [data-answer='queue']").takeIf { it.startsWith("ok") } } shouldContain "path of 2 points"
            browser.awaitTrue("the sim at the first point", 60.seconds) { gcs.sim[1].distanceTo(points[0]) < 3 }
            browser.awaitTrue("the sim at the second point", 60.seconds) { gcs.sim[1].distanceTo(points[1]) < 3 }
            browser.awaitTrue("the queue empty once the path's end is reached") { browser.textOf("#queue-panel .queue-status .current").contains("nothing") }

            // A long path, cleared on its way: the queue empties and the vehicle stops short of it.
            val far = gcs.sim[1].offset(0.0, -150.0)
            browser.find("#queue-panel button[data-queue-tool='path']").click()
            browser.clickMap(far)
            browser.find("#queue-panel button[data-queue='finish']").click()
            browser.awaitTrue("the sim on its way", 60.seconds) { gcs.sim[1].distanceTo(points[1]) > 20 }
            browser.find("#queue-panel button[data-queue='clear']").click()
            browser.await("clear's answer") { browser.textOf("#queue-panel [data-answer='queue']").takeIf { it.startsWith("ok") } } shouldStartWith "ok"
            browser.awaitTrue("the queue empty on the page") { browser.textOf("#queue-panel .queue-status .current").contains("nothing") }
            browser.awaitTrue("the sim holding", 60.seconds) { gcs.sim[1].groundSpeed < 0.3 }
            (gcs.sim[1].distanceTo(far) > 50) shouldBe true
        }
    }

    "a vehicle lost while flying its queue ends the flight, with the reason on the page and in the log" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            gcs.flyingOnPage(browser, height = 10.0)
            val far = gcs.sim[1].offset(0.0, 250.0)
            browser.find("#queue-panel button[data-queue-tool='goto']").click()
            browser.clickMap(far)
            browser.awaitTrue("the queue flown", 30.seconds) { browser.textOf("#queue-panel [data-queue-flight]") == "flying its queue" }
            browser.awaitTrue("the sim on its way") { gcs.sim[1].groundSpeed > 1 }
            gcs.sim[1].stop()
            val ended = browser.await("the flight's end on the page", 60.seconds) { browser.textOf("#queue-panel [data-queue-flight]").takeIf { it.startsWith("flight ended") } }
            ended shouldContain "vehicle 1 was lost"
            browser.find("#queue-panel [data-queue-flight]").getAttribute("class") shouldContain "bad"
            // Cleared, so the map does not show as flown what nothing flies.
            browser.textOf("#queue-panel .queue-status .current") shouldContain "nothing"
            val logged = ArrayList<pod.cli.json.Event>()
            gcs.fleet.followLog { synchronized(logged) { logged += it } }()
            synchronized(logged) { logged.filterIsInstance<PageAction>().single { it.action == "fly the queue" } }.detail.orEmpty() shouldContain "was lost"
            browser.screenshot("queue-vehicle-lost")
        }
    }
})
