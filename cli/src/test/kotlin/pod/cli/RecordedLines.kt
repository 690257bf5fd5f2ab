package pod.cli

import java.util.concurrent.CopyOnWriteArrayList

/** The lines a view or command printed, as a test reads them. */
internal class RecordedLines : Output {
    val lines = CopyOnWriteArrayList<String>()

    override fun line(text: String) {
        lines += text
    }
}
