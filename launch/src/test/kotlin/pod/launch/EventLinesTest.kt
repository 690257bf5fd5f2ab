package pod.launch

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import pod.core.engine.EngineEvent
import pod.core.platform.MissionEvent
import kotlin.time.Duration.Companion.seconds

class EventLinesTest : StringSpec({
    val lines = EventLines { "copter-$it" }

    "one step is a step, not '1 steps'" {
        lines.line(EngineEvent.Mission(75.seconds, 1, 2, MissionEvent.Uploaded(1))) shouldBe "01:15  copter-2 mission on board (1 step)"
        lines.line(EngineEvent.Mission(75.seconds, 1, 2, MissionEvent.Uploaded(3))) shouldBe "01:15  copter-2 mission on board (3 steps)"
        lines.line(EngineEvent.Mission(75.seconds, 1, 2, MissionEvent.Uploaded(0))) shouldBe "01:15  copter-2 mission on board (0 steps)"
    }

    "what the vehicle was changed to fly, and a loiter that lasts, are said; steps count from 1" {
        lines.line(EngineEvent.Mission(3.seconds, 1, 2, MissionEvent.Prepared(listOf("mode STABILIZE → GUIDED", "armed")))) shouldBe
            "00:03  copter-2 ready to fly: mode STABILIZE → GUIDED, armed"
        lines.line(EngineEvent.Mission(90.seconds, 1, 2, MissionEvent.Loitering(2))) shouldBe "01:30  copter-2 loitering at step 3, until the task is cancelled"
        lines.line(EngineEvent.Mission(90.seconds, 1, 2, MissionEvent.StepDone(0))) shouldBe "01:30  copter-2 step 1 done"
    }
})
