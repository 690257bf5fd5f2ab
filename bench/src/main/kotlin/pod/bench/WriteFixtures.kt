package pod.bench

import java.io.File

/**
 * Writes each [Fixtures.Sample]'s datagram to `<dir>/<NAME>.bin`, so that pymavlink_decode.py
 * decodes exactly the bytes the JMH benchmarks decode.
 *
 * Usage: `WriteFixturesKt <dir>`.
 */
fun main(args: Array<String>) {
    val dir = File(args.singleOrNull() ?: error("usage: WriteFixturesKt <output dir>"))
    dir.mkdirs()
    for (sample in Fixtures.Sample.entries) {
        val bytes = sample.datagram()
        File(dir, "${sample.name}.bin").writeBytes(bytes)
        println("fixture ${sample.name}: ${bytes.size} bytes ${bytes.joinToString("") { "%02x".format(it) }}")
    }
}
