package pod.core.engine

import pod.core.time.virtualTimebase
import io.kotest.assertions.withClue
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.currentTime
import pod.core.platform.MissionEvent
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.VehicleLost
import kotlin.random.Random
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** One program of a [Scenario]: its tree, tagged in mission names, and when it is cancelled (or never). */
internal data class ProgramPlan(val tag: String, val plan: TaskPlan, val cancelAt: Duration?) {
    /** When the program must have ended, however it ends. */
    val deadline: Duration get() = bound(plan).let { b -> cancelAt?.let { minOf(b, it + SAFE_TIME) } ?: b }

    override fun toString() = "program $tag (cancel at $cancelAt, deadline $deadline): $plan"
}

/** A vehicle that goes LOST at [at] and, unless [back] is null, is heard again then. */
internal data class Outage(val vehicle: Int, val at: Duration, val back: Duration?) {
    /** True when a flight of [vehicle] ending at [time] may have been left alone because the vehicle was lost. */
    fun covers(vehicle: Int, time: Duration) = vehicle == this.vehicle && time >= at && (back == null || time <= back)
}

/** One generated case: a fleet, one program or two at once on one engine, and a vehicle outage or none. */
internal data class Scenario(
    val vehicles: Int,
    val batteries: List<Double>,
    val programs: List<ProgramPlan>,
    val outage: Outage?,
    val connectionTimeout: Duration,
) {
    override fun toString() = "$vehicles vehicles at $batteries, outage $outage, connection timeout $connectionTimeout:\n  " +
        programs.joinToString("\n  ")

    companion object {
        fun generate(random: Random): Scenario {
            val vehicles = random.nextInt(2, 5)
            val programs = List(if (random.nextInt(5) == 0) 2 else 1) { i ->
                val tag = "abc"[i].toString()
                val plan = TaskPlanGenerator(random, vehicles, tag).plan()
                ProgramPlan(tag, plan, if (random.nextInt(3) == 0) someTime(random, plan) else null)
            }
            val outage = if (random.nextInt(4) == 0) {
                val at = someTime(random, programs.first().plan)
                Outage(random.nextInt(1, vehicles + 1), at, if (random.nextBoolean()) at + random.nextInt(1, 10).seconds else null)
            } else {
                null
            }
            return Scenario(
                vehicles = vehicles,
                batteries = List(vehicles) { listOf(1.0, 0.9, 0.75).random(random) },
                programs = programs,
                outage = outage,
                connectionTimeout = listOf(Duration.ZERO, 5.seconds).random(random),
            )
        }

        private fun someTime(random: Random, plan: TaskPlan) = random.nextLong(0, bound(plan).inWholeMilliseconds.coerceAtLeast(1)).milliseconds
    }
}

/** How a program ended. */
internal sealed interface Outcome {
    data object Completed : Outcome

    data class Failed(val error: Throwable) : Outcome

    data object Cancelled : Outcome
}

/** What running a [Scenario] produced. */
internal class ScenarioResult(
    /** How each program ended, by tag. */
    val outcomes: Map<String, Outcome>,
    val events: List<EngineEvent>,
    val journal: List<JournalPlatform.Entry>,
)

/**
 * Runs the programs of [scenario] at once on one engine over a fresh fake fleet in this test's
 * virtual time and checks every invariant the engine promises; returns what happened, for the
 * spec's coverage counts.
 */
internal fun TestScope.runAndCheck(scenario: Scenario): ScenarioResult {
    val fleet = FakeFleet(scenario.vehicles, stepTime = STEP_TIME, drainPerStep = 0.05)
    fleet.fakes.forEachIndexed { i, v -> v.setBattery(scenario.batteries[i]) }
    val platform = JournalPlatform(fleet) { currentTime.milliseconds }
    val engine = Engine(platform, EngineConfig(timebase = virtualTimebase()))
    val clock = MutableStateFlow(Duration.ZERO)

    val events = mutableListOf<EngineEvent>()
    val collector = launch(start = CoroutineStart.UNDISPATCHED) { engine.events.collect { events += it } }
    val outcomes = mutableMapOf<String, Outcome>()
    val endedAt = mutableMapOf<String, Duration>()
    val programs = scenario.programs.map { p ->
        val task = build(p.plan, fleet, clock)
        launch(start = CoroutineStart.UNDISPATCHED) {
            try {
                engine.run {
                    connectionTimeout = scenario.connectionTimeout
                    execute(task)
                }
                outcomes[p.tag] = Outcome.Completed
            } catch (e: CancellationException) {
                outcomes[p.tag] = Outcome.Cancelled
                throw e
            } catch (e: Throwable) {
                outcomes[p.tag] = Outcome.Failed(e)
            } finally {
                endedAt[p.tag] = currentTime.milliseconds
                platform.programReturned(p.tag)
            }
        }
    }
    val outside = buildList {
        val times = scenario.programs.flatMapTo(sortedSetOf()) { clockTimes(it.plan) }
        add(
            launch {
                for (at in times) {
                    delay(at - currentTime.milliseconds)
                    clock.value = at
                }
            },
        )
        scenario.programs.forEachIndexed { i, p -> p.cancelAt?.let { at -> add(launch { delay(at); programs[i].cancel() }) } }
        scenario.outage?.let { (id, at, back) ->
            add(
                launch {
                    delay(at)
                    fleet[id].connection.value = ConnectionState.LOST
                    if (back != null) {
                        delay(back - at)
                        fleet[id].connection.value = ConnectionState.CONNECTED
                    }
                },
            )
        }
    }

    testScheduler.advanceTimeBy(scenario.programs.maxOf { it.deadline })
    testScheduler.runCurrent()
    val running = scenario.programs.filterIndexed { i, _ -> !programs[i].isCompleted }
    programs.forEach { it.cancel() }
    outside.forEach { it.cancel() }
    testScheduler.advanceUntilIdle()
    collector.cancel()
    withClue("(d) programs still running at their deadline: $running; busy ${engine.busy.value}") { running.shouldBeEmpty() }
    for (p in scenario.programs) {
        withClue("(d) program ${p.tag} ended at ${endedAt[p.tag]}, after its deadline ${p.deadline}") { (endedAt.getValue(p.tag) <= p.deadline) shouldBe true }
    }

    val result = ScenarioResult(outcomes.toMap(), events.toList(), platform.journal.toList())
    withClue("(a) the fake fleet saw a vehicle fly two missions at once") { fleet.overlaps.value shouldBe 0 }
    result.outcomes.values.forEach { checkFailure(it) }
    checkReleased(engine, fleet, result)
    checkMadeSafe(scenario, result)
    checkEventTree(result)
    return result
}

/** A program fails only with what the tree can throw. */
private fun checkFailure(outcome: Outcome) {
    val error = (outcome as? Outcome.Failed)?.error ?: return
    val expected = error is VehicleBusy || error is VehicleLost || error is PickTimeout ||
        (error is IllegalStateException && error.message.orEmpty().contains("failed on"))
    withClue("unexpected failure: $error\n${error.stackTraceToString()}") { expected shouldBe true }
}

/** (b) Nothing is held, nothing is airborne, and a new program can pick every connected vehicle at once. */
private fun TestScope.checkReleased(engine: Engine, fleet: FakeFleet, result: ScenarioResult) {
    withClue("(b) busy after the program ended") { engine.busy.value shouldBe emptyMap() }
    withClue("(b) airborne after the program ended") { fleet.airborne.shouldBeEmpty() }
    val held = mutableSetOf<Int>()
    for (event in result.events) {
        when (event) {
            is EngineEvent.Picked -> event.vehicles.forEach { id -> withClue("(b) vehicle $id picked twice at ${event.at}") { held.add(id) shouldBe true } }
            is EngineEvent.Released -> event.vehicles.forEach { id -> withClue("(b) vehicle $id released but not held at ${event.at}") { held.remove(id) shouldBe true } }
            else -> Unit
        }
    }
    withClue("(b) picked and never released") { held.shouldBeEmpty() }
    val connected = fleet.fakes.filter { it.connection.value == ConnectionState.CONNECTED }
    if (connected.isEmpty()) return
    val before = currentTime
    var picked: Set<Int> = emptySet()
    val next = launch { picked = engine.run { pick(PickRequest(count = connected.size, timeout = 1.seconds)).ids } }
    testScheduler.runCurrent()
    withClue("(b) a new program picks every connected vehicle at once") {
        next.isCompleted shouldBe true
        picked shouldBe connected.map { it.id }.toSet()
        currentTime shouldBe before
    }
}

/**
 * (c) Every flight that was cancelled or failed was followed by a safe-state request for its
 * vehicle before the program returned, unless the vehicle was lost by then (a lost vehicle cannot
 * be told anything). Checked twice: on the platform's journal and on the engine's events.
 */
private fun checkMadeSafe(scenario: Scenario, result: ScenarioResult) {
    fun exempt(vehicle: Int, at: Duration) = scenario.outage?.covers(vehicle, at) == true
    val returned = scenario.programs.associate { p -> p.tag to result.journal.indexOfFirst { it is JournalPlatform.Entry.ProgramReturned && it.tag == p.tag } }
    withClue("the journal records every program's return: $returned") { returned.values.none { it < 0 } shouldBe true }
    result.journal.forEachIndexed { i, entry ->
        if (entry !is JournalPlatform.Entry.FlightEnded || entry.completed || entry.lost || exempt(entry.vehicle, entry.at)) return@forEachIndexed
        val tag = scenario.programs.first { entry.mission.removePrefix("fail-").removePrefix("m-").startsWith(it.tag) }.tag
        val safe = (i + 1 until returned.getValue(tag)).any { (result.journal[it] as? JournalPlatform.Entry.MadeSafe)?.vehicle == entry.vehicle }
        withClue("(c) flight $entry was not followed by makeSafe before program $tag returned; journal ${result.journal}") { safe shouldBe true }
    }

    val started = result.events.withIndex().filter { it.value is EngineEvent.TaskStarted }.associate { (i, e) -> (e as EngineEvent.TaskStarted).id to i }
    val ended = result.events.withIndex().mapNotNull { (i, e) ->
        when (e) {
            is EngineEvent.TaskCancelled -> e.id to i
            is EngineEvent.TaskFailed -> e.id to i
            else -> null
        }
    }.toMap()
    val flights = result.events.withIndex().mapNotNull { (i, e) -> (e as? EngineEvent.Mission)?.takeIf { it.event is MissionEvent.Uploaded }?.let { Triple(it.task, it.vehicle, i) } }
    for ((task, vehicle, from) in flights) {
        val end = ended[task] ?: continue
        val completed = (from until end).any { (result.events[it] as? EngineEvent.Mission)?.let { m -> m.task == task && m.vehicle == vehicle && m.event == MissionEvent.Completed } == true }
        if (completed || lostBy(result.events[end], vehicle)) continue
        val safe = (from until end).any { (result.events[it] as? EngineEvent.MadeSafe)?.vehicle == vehicle }
        withClue("(c) task $task on vehicle $vehicle ended (${result.events[end]}) without a MadeSafe event; started at ${started[task]}") { safe shouldBe true }
    }
}

/** True when [end] is the failure of a flight because [vehicle] was lost (directly or suppressed by a sibling's failure). */
private fun lostBy(end: EngineEvent, vehicle: Int): Boolean {
    val error = (end as? EngineEvent.TaskFailed)?.error ?: return false
    return (listOf(error) + error.suppressed).any { it is VehicleLost && it.systemId == vehicle }
}

/** (e) Every started task ends exactly once, after it started, and after all its children ended. */
private fun checkEventTree(result: ScenarioResult) {
    val starts = mutableMapOf<Int, Pair<Int, EngineEvent.TaskStarted>>()
    val ends = mutableMapOf<Int, Int>()
    result.events.forEachIndexed { i, event ->
        val endOf = when (event) {
            is EngineEvent.TaskStarted -> {
                withClue("(e) task ${event.id} started twice") { starts.containsKey(event.id) shouldBe false }
                if (event.parent != 0) withClue("(e) task ${event.id} started outside its running parent ${event.parent}") {
                    (event.parent in starts && event.parent !in ends) shouldBe true
                }
                starts[event.id] = i to event
                null
            }
            is EngineEvent.TaskCompleted -> event.id
            is EngineEvent.TaskFailed -> event.id
            is EngineEvent.TaskCancelled -> event.id
            else -> null
        }
        if (endOf != null) {
            withClue("(e) task $endOf ended but never started, or ended twice: $event") { (endOf in starts && endOf !in ends) shouldBe true }
            ends[endOf] = i
        }
    }
    withClue("(e) tasks that never ended") { (starts.keys - ends.keys).shouldBeEmpty() }
    for ((id, start) in starts) {
        val parent = start.second.parent
        if (parent == 0) continue
        withClue("(e) task $id (${start.second.label}) ended after its parent $parent") { (ends.getValue(id) < ends.getValue(parent)) shouldBe true }
    }
}
