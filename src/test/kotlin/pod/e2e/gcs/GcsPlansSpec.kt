package pod.e2e.gcs

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.WplFile
import pod.mavlink.plan.PlanLists
import pod.mavlink.plan.QgcPlan
import pod.mavlink.plan.QgcPlanFile
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import pod.sim.SimFlavor
import pod.sim.radio.SikRadio
import java.nio.file.Files

/** [back], a plan read from a file the ground station wrote, holds [plan]'s lists (PX4 keeps them as sent). */
private fun sameLists(back: QgcPlan, plan: QgcPlan) {
    back.mission shouldBe plan.mission
    // Fence and rally travel as degrees × 10⁷ and the radius as a float: compare what the wire keeps.
    back.geoFence shouldBe PlanLists.fence(PlanLists.fenceItems(plan.geoFence))
    back.rallyPoints shouldBe PlanLists.rallyPoints(PlanLists.rallyItems(plan.rallyPoints))
}

/** The plans panel in a real browser: files dropped on the page reach the vehicle; what it holds is drawn. */
class GcsPlansSpec : StringSpec({

    "a .plan dropped on the map reaches the vehicle (mission, fence and rally), and the map draws what it holds" {
        withGcsOf(listOf(SimFlavor.PX4, SimFlavor.ARDUCOPTER)) { gcs, browser ->
            browser.openAndSelect(gcs.url, count = 2, sysid = 1)
            val plan = squarePlan()
            browser.drop("#map", "square.plan", QgcPlanFile.write(plan))
            val (kind, text) = browser.planOutcome()
            kind shouldBe "good"
            text shouldBe "uploaded square.plan to vehicle 1: 7 mission items, 5 fence items, 1 rally item"
            // PX4 keeps the items from seq 0, as QGC sends them to it (PlanOnVehicle): what it stores is the plan.
            val sim = gcs.sim[1]
            sim.missionServer.list(MissionType.MISSION) shouldBe plan.mission
            sim.missionServer.list(MissionType.FENCE) shouldBe PlanLists.fenceItems(plan.geoFence)
            sim.missionServer.list(MissionType.RALLY) shouldBe PlanLists.rallyItems(plan.rallyPoints)
            gcs.sim[2].missionServer.list(MissionType.MISSION) shouldBe emptyList()

            // Read back after the upload: the waypoints numbered 1.. as a planner does, at their places.
            val drawn = "#map .onboard .onboard-vehicle[data-sysid='1']"
            browser.awaitTrue("the on-board waypoints") { browser.findAll("$drawn .marker.waypoint").size == 5 }
            val waypoints = browser.findAll("$drawn .marker.waypoint")
            waypoints.map { it.getAttribute("data-n") } shouldBe listOf("1", "2", "3", "4", "5")
            waypoints.map { it.getAttribute("data-lat")!!.toDouble() to it.getAttribute("data-lon")!!.toDouble() } shouldBe
                plan.mission.take(5).map { it.latitude to it.longitude }
            browser.findAll("$drawn .marker.roi").map { it.getAttribute("data-n") } shouldBe listOf("6")
            browser.findAll("$drawn polygon.fence.inclusion") shouldHaveSize 1
            browser.findAll("$drawn circle.fence.exclusion") shouldHaveSize 1
            browser.findAll("$drawn .marker.rally") shouldHaveSize 1
            // The path joins home and the five navigation items, not the region of interest.
            browser.find("$drawn polyline.mission-path").getAttribute("points")!!.trim().split(" ") shouldHaveSize 6
            browser.find("#plan-transfers li[data-sysid='1']").text shouldBe "vehicle 1: uploading square.plan: done"
            browser.screenshot("plans-uploaded")
        }
    }

    "a .waypoints file chosen in the file input reaches an ArduCopter, home line and all; show on board draws a mission sent another way" {
        withGcsOf(listOf(SimFlavor.ARDUCOPTER, SimFlavor.ARDUCOPTER)) { gcs, browser ->
            browser.openAndSelect(gcs.url, count = 2, sysid = 1)
            val items = listOf(item(0, 16, nearHome(0.0, 0.0), 0f, frame = 0), item(1, 22, null, 15f)) +
                (2..4).map { i -> item(i, 16, nearHome(40.0 * i, 10.0)) }
            val file = Files.createTempFile("route", ".waypoints").also { Files.writeString(it, WplFile.write(items)) }
            try {
                browser.find("#plan-file").sendKeys(file.toString())
                val (kind, text) = browser.planOutcome()
                kind shouldBe "good"
                text shouldBe "uploaded ${file.fileName} to vehicle 1: 5 mission items"
            } finally {
                Files.deleteIfExists(file)
            }
            // Line 0 is home, ArduPilot's item 0, which it overwrites with its own; the rest as the file has them.
            val stored = gcs.sim[1].missionServer.list(MissionType.MISSION)
            stored shouldHaveSize 5
            stored.drop(1).map { listOf(it.command, it.x, it.y, it.z.toInt()) } shouldBe items.drop(1).map { listOf(it.command, it.x, it.y, it.z.toInt()) }

            // Vehicle 2 gets a mission through Pod's API, not the page: "show on board" reads it and draws it.
            val mission = listOf(item(0, 16, nearHome(0.0, 0.0), 0f, frame = 0), item(1, 22, null, 15f), item(2, 16, nearHome(-50.0, -50.0)), item(3, 16, nearHome(-50.0, 50.0)))
            gcs.sim.station.vehicles.value.getValue(2).mission.upload(mission)
            browser.find("#fleet tbody tr[data-sysid='2']").click()
            browser.find("#plan-show").click()
            val (shown, detail) = browser.planOutcome()
            shown shouldBe "good"
            detail shouldBe "vehicle 2 holds 3 mission items, 0 fence items and 0 rally points"
            val drawn = "#map .onboard .onboard-vehicle[data-sysid='2']"
            browser.awaitTrue("vehicle 2's waypoints") { browser.findAll("$drawn .marker.waypoint").size == 2 }
            browser.findAll("$drawn .marker.waypoint").map { it.getAttribute("data-seq") } shouldBe listOf("2", "3")
            browser.findAll("$drawn .marker.home-item") shouldHaveSize 1
        }
    }

    "a malformed file and an upload the vehicle refuses each show an error naming the file; nothing reaches the vehicle" {
        withGcsOf(listOf(SimFlavor.PX4)) { gcs, browser ->
            browser.openAndSelect(gcs.url, count = 1, sysid = 1)
            val badValue = """{"fileType": "Plan", "version": 1, "mission": {"version": 2, "items": [{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0, 0, 95, 8, 10]}]}}"""
            browser.drop("#plans-panel", "broken.plan", badValue)
            val (malformed, error) = browser.planOutcome()
            malformed shouldBe "bad"
            error shouldStartWith "broken.plan: plan mission.items[0].params[4]"
            browser.screenshot("plans-malformed")

            browser.drop("#map", "notes.waypoints", "QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\tnorth\t-8.59\t0\t1\n")
            val (kind, text) = browser.planOutcome()
            kind shouldBe "bad"
            text shouldStartWith "notes.waypoints: WPL line 2:"

            // 1001 items: more than the vehicle holds (1000), refused in its words (MAV_MISSION_NO_SPACE).
            val tooLong = squarePlan().let { p -> p.copy(mission = (0..1000).map { i -> item(i, 16, nearHome(i % 50 * 2.0, 0.0)) }) }
            browser.drop("#map", "too-long.plan", QgcPlanFile.write(tooLong))
            val (refused, why) = browser.planOutcome()
            refused shouldBe "bad"
            why shouldStartWith "too-long.plan: "
            why shouldContain "NO_SPACE"
            MissionType.entries.forEach { gcs.sim[1].missionServer.list(it) shouldBe emptyList() }
        }
    }

    "download plan saves what the vehicle holds as a .plan file that reads back to the same items" {
        withGcsOf(listOf(SimFlavor.PX4)) { gcs, browser ->
            val plan = squarePlan()
            val vehicle = gcs.sim.station.vehicles.value.getValue(1)
            vehicle.mission.upload(plan.mission, MissionType.MISSION)
            vehicle.mission.upload(PlanLists.fenceItems(plan.geoFence), MissionType.FENCE)
            vehicle.mission.upload(PlanLists.rallyItems(plan.rallyPoints), MissionType.RALLY)

            // The route, as any HTTP client gets it: an attachment.
            val response = withContext(Dispatchers.IO) {
                HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create("${gcs.url}api/vehicles/1/plan")).build(), HttpResponse.BodyHandlers.ofString())
            }
            response.statusCode() shouldBe 200
            response.headers().firstValue("Content-Disposition").get() shouldContain "attachment"
            response.headers().firstValue("Content-Disposition").get() shouldContain "vehicle-1.plan"
            sameLists(QgcPlanFile.read(response.body()), plan)

            // The page's button: the browser saves the file.
            val downloads = Files.createTempDirectory("pod-gcs-downloads")
            try {
                browser.driver.executeCdpCommand("Browser.setDownloadBehavior", mapOf("behavior" to "allow", "downloadPath" to downloads.toString()))
                browser.openAndSelect(gcs.url, count = 1, sysid = 1)
                browser.find("#plan-download").click()
                browser.planOutcome().first shouldBe "good"
                val saved = downloads.resolve("vehicle-1.plan")
                browser.awaitTrue("the saved file") { Files.isRegularFile(saved) && Files.size(saved) > 0 }
                sameLists(QgcPlanFile.read(saved), plan)
            } finally {
                downloads.toFile().deleteRecursively()
            }
            // A vehicle that is not on the link is a 404 saying so.
            val missing = withContext(Dispatchers.IO) {
                HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create("${gcs.url}api/vehicles/9/plan")).build(), HttpResponse.BodyHandlers.ofString())
            }
            (missing.statusCode() to missing.body()) shouldBe (404 to "no vehicle 9 on ${gcs.sim.station.link.address}")
        }
    }

    "a long upload shows its progress on the page while it runs, then how it ended" {
        // A 57600-baud telemetry radio paces the transfer as a field link does.
        withGcsOf(listOf(SimFlavor.PX4), timeScale = 2.0, configure = { it.copy(radio = SikRadio()) }) { gcs, browser ->
            browser.openAndSelect(gcs.url, count = 1, sysid = 1)
            browser.js("window.seenProgress = []; window.pod.on('plan_progress', (e) => window.seenProgress.push(e));")
            val plan = squarePlan().let { p -> p.copy(mission = (0 until 300).map { i -> item(i, 16, nearHome(i % 60 * 2.0, i / 60 * 2.0)) }) }
            browser.drop("#map", "long.plan", QgcPlanFile.write(plan))
            browser.awaitTrue("a progress bar part way") {
                browser.js("return window.seenProgress.some((e) => !e.finished && e.list === 'mission' && e.done > 0 && e.done < e.total)") == true
            }
            // Read in the page in one go: the row moves on as the batches come.
            browser.awaitTrue("the panel's row part way") {
                browser.js(
                    """
                    const row = document.querySelector("#plan-transfers li[data-sysid='1']");
                    const part = row && /uploading long.plan: mission (\d+)\/300$/.exec(row.firstChild.textContent);
                    return part != null && Number(part[1]) > 0 && Number(part[1]) < 300 && row.lastChild.value == Number(part[1]);
                    """.trimIndent(),
                ) == true
            }
            browser.screenshot("plans-progress")
            browser.planOutcome().first shouldBe "good"
            browser.awaitTrue("the transfer ended") { browser.find("#plan-transfers li[data-sysid='1']").getAttribute("class") == "finished" }
            gcs.sim[1].missionServer.list(MissionType.MISSION) shouldBe plan.mission
        }
    }
})
