package pod.cli.json

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe

/** The plans panel's events (PlanEvents.kt), for EventJsonTest's samples of every kind. */
internal val planEventSamples: List<Event> = listOf(
    PlanProgress(1, "survey.plan", "uploading", "fence", 3, 7, waiting = null),
    PlanProgress(1, "on board", "downloading", "mission", 0, 0, waiting = "the vehicle still holds an abandoned upload", finished = true, failed = true),
    PlanTransfer(1, "survey.plan", "upload", ok = false, error = "upload of mission rejected by the vehicle: NO_SPACE", items = mapOf("mission" to 7)),
    OnBoard(
        sysid = 1,
        mission = listOf(OnBoardItem(seq = 1, n = 1, command = 16, lat = 41.1, lon = -8.6, alt = 30.0, nav = true)),
        polygons = listOf(OnBoardPolygon(true, listOf(listOf(41.1, -8.6), listOf(41.2, -8.6), listOf(41.2, -8.5)))),
        circles = listOf(OnBoardCircle(false, 41.15, -8.55, 25.0)),
        rally = listOf(OnBoardRally(41.12, -8.58, null)),
        home = listOf(41.1, -8.6),
        missionItems = 3,
    ),
    GcsServing("http://127.0.0.1:8080/"),
)

class PlanEventsTest : StringSpec({
    "the plans panel's events encode to one line and decode back to the same event" {
        for (event in planEventSamples) {
            val line = EventJson.encode(event)
            line.contains('\n') shouldBe false
            EventJson.decode(line) shouldBe event
        }
        EventJson.encode(planEventSamples.first()) shouldBe
            """{"event":"plan_progress","sysid":1,"file":"survey.plan","action":"uploading","list":"fence","done":3,"total":7,"waiting":null,"finished":false,"failed":false}"""
    }
})
