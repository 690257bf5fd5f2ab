// A program that idles long enough for a test to look at the page `pod run --gcs` serves (GcsProgramSpec); stopped by a signal.
@file:DependsOn("pod:pod-launch:0.1.0")
@file:DependsOn("pod:pod-dsl:0.1.0")

import pod.dsl.*
import pod.launch.pod
import kotlin.time.Duration.Companion.minutes

pod {
    message("gcs script started")
    execute(idle(30.minutes))
}
