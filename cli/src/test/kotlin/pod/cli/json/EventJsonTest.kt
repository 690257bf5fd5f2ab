package pod.cli.json

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.SerializationException
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import pod.core.engine.EngineEvent
import pod.core.platform.MissionEvent
import pod.cli.queue.ElementJson
import pod.cli.queue.EntryJson
import pod.cli.queue.PatternJson
import pod.cli.queue.PointJson
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

private val circleEntry = EntryJson(2, ElementJson(PatternJson.Circle(PointJson.Local(300.0, 0.0), -30.0), durationS = 30.0, altM = 25.0))
private val gotoEntry = EntryJson(1, ElementJson(PatternJson.Goto(PointJson.Global(41.2, -8.6))))

/** One event of every kind `pod … --json` prints, with every field set where it can be. */
private val samples: List<Event> = listOf(
    Event.PodVersion("0.1.0"),
    Event.Listening("udpin://0.0.0.0:14550", 14550),
    Event.Found(42, 1, "QUADROTOR", "ARDUPILOT"),
    Event.Lost(42, 1, "QUADROTOR", "ARDUPILOT", silenceMs = 3012),
    Event.Regained(42, 1, "QUADROTOR", "ARDUPILOT"),
    Event.Radio(51, 68, rssi = 180, remrssi = 175, noise = 40, remnoise = 38, txbuf = 97, rxerrors = 3, fixed = 1),
    Event.Telemetry(
        sysid = 42, connected = true, lat = 41.1234567, lon = -8.54321, altMsl = 95.5, altRel = 12.3, heading = 90.0,
        battery = 0.87, voltage = 12.4, mode = "AUTO", armed = true, landed = "IN_AIR", gpsFix = "FIX_3D", satellites = 10,
        link = 0.99, lostFrames = 2,
    ),
    Event.Started(1, "QUADROTOR", "PX4", 40123, "udpout://127.0.0.1:14550"),
    RouteSummary("udpin://0.0.0.0:14550", 14550, 2, 1200, 640, 3, 1, 0, 0, error = null, final = true),
    Event.Waiting(7, "a GPS fix"),
    Event.Progress("uploading", 3, 25),
    Event.Done("param-get", 7, "STABILIZE", false, 0.0, items = null, name = "WPNAV_SPEED", value = 500.0, type = "REAL32"),
    Event.Error("vehicle 7 refused: MAV_CMD_COMPONENT_ARM_DISARM was DENIED"),
    Event.Warning("survey.plan: mission.items[2] is a survey; read as its 14 expanded items"),
    Event.Interrupted("SIGINT", 7, safe = true, state = "holding in BRAKE", mode = "BRAKE", armed = true, relativeAltM = 11.9),
    Event.QueueServing(61, "127.0.0.1:14660", "GUIDED", 20.1),
    Event.QueueStarted(12.5, 61, circleEntry),
    Event.QueueEnded(42.5, 61, circleEntry, "elapsed"),
    Event.QueueEmptied(42.5, 61),
    Event.QueueStatus(61, "GUIDED", true, 20.1, circleEntry, remainingS = 17.5, pending = listOf(gotoEntry)),
    Event.QueueDone("prepend", 61, entry = circleEntry, ended = null, current = circleEntry, remainingS = 30.0, pending = listOf(gotoEntry)),
    Event.TaskStarted(1.5, 3, 1, "survey", listOf(1, 2)),
    Event.TaskDone(61.25, 3, "survey"),
    Event.TaskFailed(61.25, 4, "hop", "vehicle 2 lost"),
    Event.TaskCancelled(61.25, 5, "watch battery"),
    Event.Flying(2.0, 3, 1, "survey-1", 14),
    Event.Mission(30.0, 3, 1, "step_done", step = 4, steps = null),
    Event.Mission(2.5, 3, 1, "prepared", step = null, steps = null, changes = listOf("mode STABILIZE → GUIDED", "armed")),
    Event.MadeSafe(62.0, 2, "RETURN_HOME", confirmed = false),
    Event.Picked(0.5, listOf(1, 2)),
    Event.Released(600.0, listOf(1)),
    Event.Message(600.0, "listing 4: time is up; bringing \"a\" home\n"),
    Event.DemoDone(ok = false, error = "vehicle 3 lost", map = "pod-demo-map.svg"),
    Event.Replaying("flight.tlog", 10.0),
    Event.ReplayDone(records = 5120, logS = 312.5, error = "tlog ends inside the record at byte 9000: it needs 29 bytes, 7 are left", map = null),
    Event.SurveyDone(ok = true, error = null, photos = 16, detections = 8, flagged = listOf(2, 6), backward = listOf(Event.Measured(6, 30.4), Event.Measured(2, null)), map = "pod-survey-map.svg"),
) + gcsEventSamples + planEventSamples

/** Every `event` name the model knows, read from its serializer (so a new kind must get a sample above). */
@OptIn(ExperimentalSerializationApi::class)
private val kinds: Set<String> = Event.serializer().descriptor.getElementDescriptor(1).let { d -> List(d.elementsCount, d::getElementName).toSet() }

class EventJsonTest : StringSpec({

    "every event kind encodes to one line and decodes back to the same event" {
        samples.map { it.kind() }.toSet() shouldBe kinds
        for (event in samples) {
            val line = EventJson.encode(event)
            withClue(line) {
                line.contains('\n') shouldBe false
                EventJson.decode(line) shouldBe event
            }
        }
    }

    "every line names its kind in the event field first and prints every field, null included" {
        val line = EventJson.encode(Event.Interrupted("SIGTERM", map = "map.svg"))
        line shouldBe """{"event":"interrupted","signal":"SIGTERM","sysid":null,"safe":null,"state":null,"mode":null,"armed":null,"relative_alt_m":null,"map":"map.svg"}"""
    }

    "a done line of an action and a telemetry line keep their snake_case field names" {
        EventJson.encode(Event.Done("takeoff", 51, "GUIDED", true, 12.0)) shouldBe
            """{"event":"done","action":"takeoff","sysid":51,"mode":"GUIDED","armed":true,"relative_alt_m":12.0,"items":null,"name":null,"value":null,"type":null,"requested":null}"""
        EventJson.encode(samples.first { it is Event.Telemetry }) shouldBe
            """{"event":"telemetry","sysid":42,"connected":true,"lat":41.1234567,"lon":-8.54321,"alt_msl":95.5,"alt_rel":12.3,""" +
            """"heading":90.0,"battery":0.87,"voltage":12.4,"mode":"AUTO","armed":true,"landed":"IN_AIR","gps_fix":"FIX_3D","satellites":10,""" +
            """"link":0.99,"lost_frames":2}"""
        EventJson.encode(Event.Waiting(7, "a GPS fix")) shouldBe
            """{"event":"waiting","sysid":7,"for":"a GPS fix","heard":null,"attempt":null,"waited_s":null,"timeout_s":null}"""
    }

    "numbers that are not finite are written as null and read back as null" {
        val telemetry = Event.Telemetry(
            sysid = 1, connected = false, lat = Double.NaN, lon = Double.POSITIVE_INFINITY, altMsl = Double.NEGATIVE_INFINITY,
            altRel = null, heading = null, battery = Double.NaN, voltage = null, mode = null, armed = false, landed = "UNDEFINED",
            gpsFix = null, satellites = null, link = Double.NaN, lostFrames = 0,
        )
        val fields = Json.parseToJsonElement(EventJson.encode(telemetry)).jsonObject
        for (name in listOf("lat", "lon", "alt_msl", "battery", "link")) withClue(name) { fields.getValue(name) shouldBe JsonNull }
        EventJson.decode(EventJson.encode(telemetry)) shouldBe telemetry.copy(lat = null, lon = null, altMsl = null, battery = null, link = null)
    }

    "a line that is not one of the model's events does not decode" {
        shouldThrow<SerializationException> { EventJson.decode("""{"event":"teleported","sysid":1}""") }
        shouldThrow<SerializationException> { EventJson.decode("""{"event":"error","message":"x","extra":1}""") }
        shouldThrow<SerializationException> { EventJson.decode("""{"event":"progress","action":"uploading","done":1}""") }
        shouldThrow<SerializationException> { EventJson.decode("""{"message":"no kind"}""") }
    }

    "a mission event says what happened in fields, not as an object's toString" {
        val at = 61_250.milliseconds
        EventJson.encode(EngineEvent.Mission(at, task = 3, vehicle = 1, event = MissionEvent.StepDone(4)).toEvent()!!) shouldBe
            """{"event":"mission","at":61.25,"task":3,"vehicle":1,"what":"step_done","step":4,"steps":null,"changes":null}"""
        EngineEvent.Mission(at, 3, 1, MissionEvent.Prepared(listOf("mode RTL → GUIDED", "armed"))).toEvent() shouldBe
            Event.Mission(61.25, 3, 1, "prepared", null, null, changes = listOf("mode RTL → GUIDED", "armed"))
        EngineEvent.Mission(at, 3, 1, MissionEvent.Uploaded(14)).toEvent() shouldBe Event.Mission(61.25, 3, 1, "uploaded", null, 14)
        EngineEvent.Mission(at, 3, 1, MissionEvent.Started).toEvent() shouldBe Event.Mission(61.25, 3, 1, "started", null, null)
        EngineEvent.Mission(at, 3, 1, MissionEvent.Completed).toEvent() shouldBe Event.Mission(61.25, 3, 1, "completed", null, null)
        EngineEvent.Mission(at, 3, 1, MissionEvent.StepStarted(4)).toEvent() shouldBe null
    }

    "the README's --json section has a row for every event kind, naming each of its fields" {
        // Surefire runs in the module's directory; the README is the repository's.
        val readme = java.io.File("../README.md").readLines()
        for (event in samples) {
            val kind = event.kind()
            val row = readme.singleOrNull { it.startsWith("| `$kind` |") }
            withClue("README row for $kind") { (row != null) shouldBe true }
            for (field in fieldsOf(event)) withClue("README row for $kind names `$field`") { row!!.contains("`$field`") shouldBe true }
        }
    }

    "a queue entry's pattern and points name their kind in a type field, not the event field" {
        EventJson.encode(Event.QueueStarted(12.5, 61, circleEntry)) shouldBe
            """{"event":"queue_started","at_s":12.5,"sysid":61,"entry":{"id":2,"element":{"pattern":{"type":"circle","center":{"type":"local","north":300.0,"east":0.0},"radius":-30.0},"duration_s":30.0,"alt_m":25.0}}}"""
    }

    "a program's picked vehicles are a JSON array of system ids" {
        EventJson.encode(EngineEvent.Picked(2.seconds, listOf(3, 4)).toEvent()!!) shouldBe """{"event":"picked","at":2.0,"vehicles":[3,4]}"""
    }
})

private fun fieldsOf(event: Event): Set<String> = Json.parseToJsonElement(EventJson.encode(event)).jsonObject.keys - "event"

private fun Event.kind(): String = (Json.parseToJsonElement(EventJson.encode(this)) as JsonObject).getValue("event").jsonPrimitive.content
