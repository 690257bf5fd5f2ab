package pod.launch

import pod.core.engine.EngineEvent
import pod.mavlink.GroundStation

/**
 * Something outside a program that watches the fleet a [pod] program flies: `pod run --gcs`
 * serves the ground station's page for it. [watch] is called once the fleet's station is up and
 * before the program starts; the [Watch] it returns gets every event of the program and is
 * closed when the program ends, however it ends. A program does nothing to be watched: the
 * watcher is set around it with [FleetWatcher.around].
 */
public fun interface FleetWatcher {
    /**
     * Starts watching [station], whose vehicles' clocks run [timeScale] times real time;
     * [source] names the fleet for people (`4 simulated copters`, `udpin://0.0.0.0:14550`).
     */
    public suspend fun watch(station: GroundStation, timeScale: Double, source: String): Watch

    /** One watch of one program's fleet. */
    public interface Watch : AutoCloseable {
        /** The program's [event], as it happens (called from the engine's collector: hand it on, do not block). */
        public fun event(event: EngineEvent)
    }

    /** Installs the watcher that [pod] programs report to. */
    public companion object {
        @Volatile
        private var current: FleetWatcher? = null

        /** The watcher [pod] programs started in this JVM now get, if any. */
        public val installed: FleetWatcher? get() = current

        /**
         * Runs [block] with [watcher] watching every [pod] program it starts (in this JVM: a
         * `pod run` script runs in the CLI's), then puts back what was there before.
         */
        public fun <T> around(watcher: FleetWatcher, block: () -> T): T {
            val before = current
            current = watcher
            try {
                return block()
            } finally {
                current = before
            }
        }
    }
}
