// A program that fails several lines below `pod {` (ScriptRunSpec): `-- nested` in a function it calls, otherwise in Pod's pick.
import pod.dsl.*
import pod.launch.pod
import kotlin.time.Duration.Companion.seconds

fun atMostTwo(count: Int): Int {
    require(count <= 2) { "at most 2 vehicles fly here, asked for $count" }
    return count
}

pod {
    message("program started")
    val count = if (args.firstOrNull() == "nested") listOf(1, 3).map { atMostTwo(it) }.last() else 2

    pick { count(count); timeout(1.seconds) }
}
