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
})
