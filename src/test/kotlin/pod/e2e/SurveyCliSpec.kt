package pod.e2e

import com.github.ajalt.clikt.core.parse
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainInOrder
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import pod.cli.Pod
import pod.cli.json.Event
import io.kotest.matchers.collections.shouldContain as shouldContainElement

/** `pod survey`: the I-Seed sample on a simulated drone over real UDP, with its map. */
class SurveyCliSpec : StringSpec({

    "pod survey flies the I-Seed scenario: the app's states in order, both passes summed up, and a map with the polygon, the paths and the detections" {
        val out = Captured()
        val map = kotlin.io.path.createTempFile("pod-survey", ".svg")
        Pod(out).parse(listOf("survey", "--time-scale", "100", "--seed", "7", "--map", map.toString()))
        val app = out.lines.filter { it.contains("app: ") }.map { it.substringAfter("app: ").substringBefore(" (event").substringBefore(",") }
        app.distinct() shouldContainInOrder listOf(
            "drone ready", "executing the forward pass", "paused in the forward pass at waypoint 4",
            "executing the backward pass", "executing the home pass", "finished: landed at home",
        )
        val forward = out.lines.single { it.startsWith("forward: ") }
        Regex("""(\d+) waypoints flagged""").find(forward)!!.groupValues[1].toInt() shouldBeGreaterThan 0
        out.lines.count { it.startsWith("backward: waypoint ") } shouldBe Regex("""(\d+) waypoints flagged""").find(forward)!!.groupValues[1].toInt()
        out.lines.last() shouldBe "survey done; map: $map"
        val svg = map.toFile().readText()
        for (layer in listOf("survey-area", "forward-path", "detections", "backward-path", "legend")) svg shouldContain "id=\"$layer\""
    }

    "pod survey --json: the app's states as message events and a survey_done line that sums up both passes" {
        val out = Captured()
        val map = kotlin.io.path.createTempFile("pod-survey-json", ".svg")
        Pod(out).parse(listOf("survey", "--json", "--time-scale", "100", "--seed", "3", "--map", map.toString()))
        val events = out.events
        events.filterIsInstance<Event.Message>().map { it.text }.filter { it.startsWith("app: ") }.last() shouldContain "finished: landed at home"
        val done = events.last() as Event.SurveyDone
        done.ok shouldBe true
        done.map shouldBe map.toString()
        (done.photos!! > 0) shouldBe true
        done.backward!!.map { it.waypoint }.sorted() shouldBe done.flagged!!.sorted()
        done.backward!!.forEach { (it.rangeM!! in 24.0..36.0) shouldBe true }
        events.filterIsInstance<Event.TaskDone>().map { it.task } shouldContainElement "survey"
    }
})
