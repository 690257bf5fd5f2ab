package pod.mavlink.mission

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.longs.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.enum
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import io.dronefleet.mavlink.minimal.MavAutopilot
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.withTimeoutOrNull
import pod.mavlink.MavlinkVehicle
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.MissionServerFlavor
import kotlin.random.Random
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds

/** A list of [count] valid items of [type], with varied frames, commands and values. */
internal fun randomItems(type: MissionType, count: Int, random: Random): List<MissionItem> = List(count) { seq ->
    val command = when (type) {
        MissionType.MISSION -> listOf(16, 22, 21, 17, 19, 178, 183).random(random)
        MissionType.FENCE -> listOf(5000, 5001, 5002, 5003, 5004).random(random)
        MissionType.RALLY -> 5100
    }
    MissionItem(
        seq = seq,
        frame = if (type == MissionType.MISSION && command >= 100) MissionItem.FRAME_MISSION else listOf(0, 3, 6, 10).random(random),
        command = command,
        current = type == MissionType.MISSION && seq == 0,
        param1 = random.nextInt(-100, 100).toFloat(),
        param2 = random.nextFloat(),
        param3 = random.nextInt(0, 5).toFloat(),
        // ArduPilot refuses a NaN param4 except where it means "keep the heading" (sanity_check_params).
        param4 = if (command in setOf(16, 21, 22) && random.nextBoolean()) Float.NaN else random.nextFloat() * 360,
        x = random.nextInt(-900_000_000, 900_000_001),
        y = random.nextInt(-1_800_000_000, 1_800_000_001),
        z = random.nextInt(-100, 3000).toFloat(),
        missionType = type,
    )
}

/** Items as a vehicle stores them: none current (the server tracks the current item itself). */
private fun List<MissionItem>.stored() = map { it.copy(current = false) }

/** Items as a [flavor] vehicle keeps them: ArduPilot in its own packed form, PX4 as sent. */
internal fun List<MissionItem>.storedBy(flavor: MissionServerFlavor) =
    if (flavor == MissionServerFlavor.ARDUPILOT) ArduPilotMissionStorage.stored(this, fixedWing = false) else stored()

/** How a mission call ended: its result, or the [MissionException] it threw. */
private sealed interface Ended<out T> {
    data class Done<T>(val value: T) : Ended<T>
    data class Failed(val error: MissionException) : Ended<Nothing>
}

/**
 * Runs [call] to its end, or null when it is still going after [limit] of virtual time (generous:
 * what is tested is that every transfer ends).
 */
private suspend fun <T> ending(limit: kotlin.time.Duration = 3.hours, call: suspend () -> T): Ended<T>? =
    withTimeoutOrNull(limit) {
        try {
            Ended.Done(call())
        } catch (e: MissionException) {
            Ended.Failed(e)
        }
    }

/**
 * The lists a vehicle of [flavor] may hold after an upload of [items] over [old] that ended any
 * way: the old list or the new one; and ArduPilot, which stores each MISSION item as it arrives
 * after cutting the list to the new count (MissionItemProtocol::handle_mission_item,
 * MissionItemProtocol_Waypoints::truncate), also the new items up to where the upload stopped and
 * the old ones after them.
 */
private fun mayHold(type: MissionType, flavor: MissionServerFlavor, old: List<MissionItem>, items: List<MissionItem>): List<List<MissionItem>> {
    val before = old.storedBy(flavor)
    val after = items.storedBy(flavor)
    if (flavor != MissionServerFlavor.ARDUPILOT || type != MissionType.MISSION) return listOf(before, after)
    return listOf(before) + (0..after.size).map { k -> after.take(k) + before.take(after.size).drop(k) }
}

/** What a download gives back from a vehicle that holds [held] (the current item flagged in a mission). */
private fun downloaded(type: MissionType, held: List<MissionItem>, server: MissionServer) =
    if (type == MissionType.MISSION) held.mapIndexed { i, it -> it.copy(current = i == server.current) } else held

/**
 * Every property runs the real [MissionService] of a real [pod.mavlink.GroundStation] against a
 * [MissionServer] behind a [MissionVehicle], on a seeded lossy [pod.mavlink.link.MemoryNetwork]
 * in virtual time: the driver, the machines and the lost-ack check are the ones in production.
 */
class MissionTransferPropertyTest : StringSpec({

    "random lists over links with up to 30% loss plus duplication and reordering: uploaded and downloaded identical, or a typed failure, never a mix but ArduPilot's half-written mission" {
        checkAll(
            PropTestConfig(iterations = 100, seed = 20261122),
            Arb.enum<MissionType>(), Arb.int(0..1000), Arb.enum<MissionServerFlavor>(),
            Arb.double(0.0, 0.3, includeNaNs = false), Arb.double(0.0, 0.2, includeNaNs = false), Arb.long(),
        ) { type, count, flavor, drop, duplicate, seed ->
            val random = Random(seed)
            val old = randomItems(type, random.nextInt(0, 20), random)
            val items = randomItems(type, count, random)
            val server = MissionServer(flavor, maxItems = 1000).apply { load(type, old.storedBy(flavor)) }
            val faults = Faults(drop = drop, duplicate = duplicate, minDelayMs = 5, maxDelayMs = 60, hold = duplicate / 2)
            runTest {
                onLossyLink(server, faults, faults, seed) { vehicle, _ ->
                    val outcome = ending { vehicle.mission.upload(items, type) }
                    withClue("upload of $count ${type.name} items, drop $drop, dup $duplicate, ${flavor.name}: must end, not hang") {
                        outcome.shouldNotBeNull()
                    }
                    val held = server.list(type)
                    withClue("the vehicle holds the old list or the new one (or ArduPilot's half-written mission), never another mix") {
                        (held in mayHold(type, flavor, old, items)) shouldBe true
                    }
                    if (outcome is Ended.Done) held shouldBe items.storedBy(flavor)

                    val back = ending { vehicle.mission.download(type) }
                    withClue("download must end") { back.shouldNotBeNull() }
                    if (back is Ended.Done) back.value shouldBe downloaded(type, held, server)
                }
            }
        }
    }

    "an upload cancelled at a random moment over a lossy link leaves the vehicle with the old list or the new one (ArduPilot's mission: half-written), idle, and ready for the next upload" {
        checkAll(
            PropTestConfig(iterations = 100, seed = 20261123),
            Arb.enum<MissionType>(), Arb.int(1..300), Arb.enum<MissionServerFlavor>(),
            Arb.double(0.0, 0.3, includeNaNs = false), Arb.long(0L..3_000L), Arb.long(),
        ) { type, count, flavor, drop, cancelAtMs, seed ->
            val random = Random(seed)
            val old = randomItems(type, random.nextInt(0, 20), random)
            val items = randomItems(type, count, random)
            val server = MissionServer(flavor, maxItems = 1000).apply { load(type, old.storedBy(flavor)) }
            val faults = Faults(drop = drop, duplicate = 0.05, minDelayMs = 2, maxDelayMs = 20)
            runTest {
                onLossyLink(server, faults, faults, seed) { vehicle, onBoard ->
                    // Cancelled, the service tells the vehicle with MISSION_ACK OPERATION_CANCELLED.
                    val outcome = ending(cancelAtMs.milliseconds) { vehicle.mission.upload(items, type) }
                    if (outcome == null) {
                        withClue("the vehicle goes quiet after the cancel, whether or not the ACK got through") {
                            onBoard.settle() shouldBe true
                        }
                    }
                    val held = server.list(type)
                    withClue("cancelled at $cancelAtMs ms: the vehicle holds the old list or the new one (or ArduPilot's half-written mission), never another mix") {
                        (held in mayHold(type, flavor, old, items)) shouldBe true
                    }
                    val next = randomItems(type, random.nextInt(1, 50), random)
                    val again = ending { vehicle.mission.upload(next, type) }
                    withClue("the next upload after the cancel: $again") { again.shouldBeInstanceOf<Ended.Done<*>>() }
                    server.list(type) shouldBe next.storedBy(flavor)
                }
            }
        }
    }

    "partial writes into an ArduPilot vehicle over a lossy link replace exactly their range, or fail typed and leave the list whole (a mission: written up to where they stopped)" {
        var written = 0
        checkAll(
            PropTestConfig(iterations = 100, seed = 20261124),
            Arb.enum<MissionType>(), Arb.int(1..300), Arb.double(0.0, 0.3, includeNaNs = false), Arb.long(),
        ) { type, size, drop, seed ->
            val random = Random(seed)
            val old = randomItems(type, size, random).storedBy(MissionServerFlavor.ARDUPILOT)
            val first = random.nextInt(0, size)
            val count = random.nextInt(1, size - first + 1)
            val patch = randomItems(type, first + count, random).drop(first)
            val server = MissionServer(MissionServerFlavor.ARDUPILOT).apply { load(type, old) }
            val faults = Faults(drop = drop, duplicate = 0.05, minDelayMs = 2, maxDelayMs = 20)
            val expected = old.take(first) + patch.storedBy(MissionServerFlavor.ARDUPILOT) + old.drop(first + count)
            runTest {
                onLossyLink(server, faults, faults, seed) { vehicle, _ ->
                    val outcome = ending { vehicle.mission.uploadPartial(patch, type) }
                    withClue("partial write of $count items at $first into $size, drop $drop: $outcome") {
                        outcome.shouldNotBeNull()
                        val held = server.list(type).map { it.copy(current = false) }
                        if (outcome is Ended.Done) {
                            held shouldBe expected
                            written++
                        } else if (type == MissionType.MISSION) {
                            // ArduPilot stores each mission item as it arrives: the patch up to where it stopped.
                            val stored = patch.storedBy(MissionServerFlavor.ARDUPILOT)
                            (held in (0..count).map { k -> old.take(first) + stored.take(k) + old.drop(first + k) }) shouldBe true
                        } else {
                            (held == old || held == expected) shouldBe true
                        }
                    }
                }
            }
        }
        withClue("at most 30 % loss: nearly every partial write goes through") { written shouldBeGreaterThan 90 }
    }

    "a vehicle that serves downloads only in order, without saying so, is learned: 20 of 20 downloads at 10 % and 30 % loss" {
        // A PX4-flavoured server (in order only, ERROR out of turn, silent drop after 5 s idle)
        // behind a heartbeat that does not say PX4: the download starts windowed and must learn.
        val failures = ArrayList<String>()
        for (drop in listOf(0.1, 0.3)) {
            for (seed in 1L..20L) {
                val items = randomItems(MissionType.MISSION, 15, Random(seed)).storedBy(MissionServerFlavor.PX4)
                val server = MissionServer(MissionServerFlavor.PX4).apply { load(MissionType.MISSION, items) }
                val faults = Faults(drop = drop, minDelayMs = 1, maxDelayMs = 3)
                runTest {
                    onLossyLink(server, faults, faults, seed, autopilot = MavAutopilot.MAV_AUTOPILOT_GENERIC) { vehicle, _ ->
                        val outcome = ending { vehicle.mission.download() }
                        val back = (outcome as? Ended.Done)?.value?.map { it.copy(current = false) }
                        if (back != items) failures += "drop $drop seed $seed: $outcome"
                    }
                }
            }
        }
        failures shouldBe emptyList()
    }

    "with 10% loss each way, 20 seeded uploads of 200 items into either flavour all succeed" {
        val failures = ArrayList<String>()
        for (seed in 1L..20L) {
            val flavor = if (seed % 2 == 0L) MissionServerFlavor.PX4 else MissionServerFlavor.ARDUPILOT
            val items = randomItems(MissionType.MISSION, 200, Random(seed))
            val server = MissionServer(flavor)
            val faults = Faults(drop = 0.1, minDelayMs = 10, maxDelayMs = 30)
            runTest {
                onLossyLink(server, faults, faults, seed) { vehicle, _ ->
                    val outcome = ending { vehicle.mission.upload(items) }
                    if (outcome !is Ended.Done) failures += "seed $seed ${flavor.name}: $outcome"
                }
            }
        }
        failures shouldBe emptyList()
    }
})

/**
 * How fast transfers go over a lossy link, in virtual time (deterministic: the same seeds give the
 * same times on any machine). Guards the recovery paths that used to stall on the vehicle's own
 * re-request timer: a vehicle ahead of us after an unasked item, a round-trip estimate inflated by
 * the vehicle's timer, needless restarts of in-order downloads.
 */
class MissionTransferPaceTest : StringSpec({

    for (flavor in MissionServerFlavor.entries) {
        "at 30% loss each way on a 2 ms link, 100-item uploads and downloads with ${flavor.name} take a median under 6 s of virtual time" {
            val faults = Faults(drop = 0.3, minDelayMs = 1, maxDelayMs = 3)
            val uploads = ArrayList<Long>()
            val downloads = ArrayList<Long>()
            for (seed in 1L..11L) {
                val items = randomItems(MissionType.MISSION, 100, Random(seed))
                runTest {
                    onLossyLink(MissionServer(flavor), faults, faults, seed) { vehicle: MavlinkVehicle, _ ->
                        // Upload then download share the vehicle's round-trip estimate, as every transfer does.
                        val started = testScheduler.currentTime
                        ending { vehicle.mission.upload(items) }.shouldBeInstanceOf<Ended.Done<*>>()
                        uploads += testScheduler.currentTime - started
                        val downloadStarted = testScheduler.currentTime
                        ending { vehicle.mission.download() }.shouldBeInstanceOf<Ended.Done<*>>()
                        downloads += testScheduler.currentTime - downloadStarted
                    }
                }
            }
            withClue("upload ms $uploads") { uploads.sorted()[5] shouldBeLessThan 6_000L }
            withClue("download ms $downloads") { downloads.sorted()[5] shouldBeLessThan 6_000L }
        }
    }

    "a round trip the vehicle's re-request timer made up does not stretch the timeout once a real one was seen" {
        val timing = TransferTiming()
        val estimate = RoundTripEstimator(timing)
        estimate.sample(3_000_000, mayBeVehicleTimer = true)
        repeat(20) { estimate.sample(250_000_000, mayBeVehicleTimer = true) } // PX4's 250 ms re-requests
        estimate.timeoutNanos shouldBe timing.minTimeout.inWholeNanoseconds
        // An inflated start (the timer was the first thing measured) is dropped at the first real sample.
        val inflated = RoundTripEstimator(timing).apply { sample(1_000_000_000, mayBeVehicleTimer = true) }
        inflated.sample(3_000_000)
        inflated.timeoutNanos shouldBeLessThan 100_000_000L
    }
})
