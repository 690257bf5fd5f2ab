package pod.mavlink.mission

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.booleans.shouldBeTrue
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.enum
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import kotlinx.coroutines.test.runTest
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.MissionServerFlavor
import kotlin.random.Random

private const val LAT = 411_780_460
private const val LON = -85_957_860

/** Uploads [items] into [server] over a clean link and returns what a download gives back. */
private fun roundTrip(server: MissionServer, items: List<MissionItem>, type: MissionType = MissionType.MISSION): List<MissionItem> {
    var back: List<MissionItem>? = null
    runTest {
        onLossyLink(server, Faults(), Faults(), seed = 1) { vehicle, _ ->
            vehicle.mission.upload(items, type)
            back = vehicle.mission.download(type)
        }
    }
    return back!!
}

class ArduPilotMissionStorageTest : StringSpec({

    "an ArduPilot vehicle gives back its own form of a mission, as measured on ArduCopter 4.7 SITL" {
        val home = MissionItem(0, 0, 16, x = LAT, y = LON, z = 120.456f)
        val server = MissionServer(MissionServerFlavor.ARDUPILOT, home = { home })
        val sent = listOf(
            MissionItem(0, 3, 16, x = 1, y = 2, z = 5f),
            // A yaw of NaN ("keep heading") and an acceptance radius of 5 m: a copter keeps neither.
            MissionItem(1, 3, 16, param1 = 2.5f, param2 = 5f, param4 = Float.NaN, x = LAT, y = LON, z = 30f),
            // DO_CHANGE_SPEED sent in a global frame with a location: neither is kept.
            MissionItem(2, 3, 178, param1 = 1f, param2 = 7.5f, param3 = -1f, x = LAT, y = LON, z = 30f),
            MissionItem(3, 3, 19, param1 = 20f, param3 = 12f, x = LAT, y = LON, z = 40f),
            MissionItem(4, 3, 19, param1 = 20f, param3 = -10f, x = LAT, y = LON, z = 40f),
            MissionItem(5, 6, 21, param4 = Float.NaN, x = LAT, y = LON, z = 0f),
        )
        val back = roundTrip(server, sent).map { it.copy(current = false) }
        back[0] shouldBe MissionItem(0, 0, 16, x = LAT, y = LON, z = 120.45f) // home, in whole centimetres
        back[1] shouldBe MissionItem(1, 3, 16, param1 = 2f, x = LAT, y = LON, z = 30f)
        back[2] shouldBe MissionItem(2, 0, 178, param1 = 1f, param2 = 7.5f, param3 = -1f)
        back[3].param3 shouldBe 1f // NAV_LOITER_TIME keeps no radius, only its direction
        back[4].param3 shouldBe -1f
        back[5] shouldBe MissionItem(5, 3, 21, param4 = 1f, x = LAT, y = LON, z = 0f)
    }

    "fence and rally points come back from ArduPilot with autocontinue 0" {
        val server = MissionServer(MissionServerFlavor.ARDUPILOT)
        val fence = List(4) { MissionItem(it, 0, 5001, param1 = 4f, x = LAT + it * 1000, y = LON, missionType = MissionType.FENCE) }
        roundTrip(server, fence, MissionType.FENCE).map { it.autocontinue } shouldBe List(4) { false }
        val rally = listOf(MissionItem(0, 3, 5100, x = LAT, y = LON, z = 50f, missionType = MissionType.RALLY))
        roundTrip(server, rally, MissionType.RALLY).single().autocontinue shouldBe false
    }

    "ArduPilot refuses a NaN where the command has no use for one" {
        ArduPilotMissionStorage.problem(MissionItem(0, 2, 178, param4 = Float.NaN)) shouldBe MissionResult.INVALID_PARAM4
        ArduPilotMissionStorage.problem(MissionItem(0, 3, 16, param4 = Float.NaN)) shouldBe null
        ArduPilotMissionStorage.problem(MissionItem(0, 1, 16)) shouldBe MissionResult.UNSUPPORTED_FRAME
    }

    "random missions per flavour: the vehicle keeps its own form, and the comparison after a lost final ack accepts exactly that" {
        checkAll(
            PropTestConfig(iterations = 200, seed = 20261124),
            Arb.enum<MissionType>(), Arb.int(1..60), Arb.enum<MissionServerFlavor>(), Arb.long(),
        ) { type, count, flavor, seed ->
            val random = Random(seed)
            val items = randomItems(type, count, random)
            val fixedWing = random.nextBoolean()
            val server = MissionServer(flavor, fixedWing = fixedWing)
            runTest { onLossyLink(server, Faults(), Faults(), seed) { vehicle, _ -> vehicle.mission.upload(items, type) } }
            val held = server.list(type)
            val expected = if (flavor == MissionServerFlavor.ARDUPILOT) ArduPilotMissionStorage.stored(items, fixedWing) else items.map { it.copy(current = false) }
            held shouldBe expected
            val ardupilot = flavor == MissionServerFlavor.ARDUPILOT
            withClue("what the vehicle holds is recognised as what was sent") {
                MissionStorage.holds(type, held, items, ardupilot, fixedWing).shouldBeTrue()
            }
            withClue("storing twice changes nothing the comparison sees") {
                MissionStorage.holds(type, ArduPilotMissionStorage.stored(held, fixedWing), held, ardupilot = true, fixedWing = fixedWing).shouldBeTrue()
            }
            if (count > 1) {
                val other = items.toMutableList().also { it[count - 1] = it[count - 1].copy(x = it[count - 1].x xor 1, y = it[count - 1].y xor 1) }
                withClue("a list that differs where the vehicle keeps the value is not taken for it") {
                    val keepsLocation = held[count - 1].let { it.x != 0 || it.y != 0 }
                    if (keepsLocation) MissionStorage.holds(type, held, other, ardupilot, fixedWing) shouldBe false
                }
            }
        }
    }

    "an upload over a lossy link into an ArduPilot vehicle whose final ack is lost is confirmed by comparing what it keeps" {
        for (seed in 1L..20L) {
            val items = randomItems(MissionType.MISSION, 30, Random(seed))
            val server = MissionServer(MissionServerFlavor.ARDUPILOT, home = { MissionItem(0, 0, 16, x = LAT, y = LON, z = 100f) })
            val faults = Faults(drop = 0.1, minDelayMs = 5, maxDelayMs = 30)
            // Every ACCEPTED is lost, and so is every answer to a repeated last item: only a download can tell.
            val lose = { message: MissionMessage, toVehicle: Boolean -> !toVehicle && message is MissionMessage.Ack }
            runTest {
                onLossyLink(server, faults, faults, seed, lose = lose) { vehicle, _ ->
                    // Throws MissionNotConfirmed unless the download shows what was sent.
                    vehicle.mission.upload(items)
                }
            }
            withClue("seed $seed") { server.list(MissionType.MISSION).drop(1) shouldBe ArduPilotMissionStorage.stored(items, fixedWing = false).drop(1) }
        }
    }
})
