package pod.mavlink.codec

import io.dronefleet.mavlink.ardupilotmega.ArdupilotmegaDialect
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import java.lang.reflect.ParameterizedType
import java.math.BigInteger

/**
 * Checks the codec against frames that pymavlink produced (tools/gen_mavlink_vectors.py): our
 * encoder must produce the same bytes, our decoder must read them back to the same message.
 */
internal class PymavlinkVectorsTest : FunSpec({
    val codec = MessageCodec.Default
    val encoder = FrameEncoder(codec)
    val dialect = ArdupilotmegaDialect()
    val vectors = resourceLines("/vectors/pymavlink-vectors.tsv").map { Vector.parse(it) }

    test("the vector file covers both versions, signed frames and the GCS messages") {
        vectors.size shouldBeGreaterThan 100
        vectors.count { it.version == 1 } shouldBeGreaterThan 40
        vectors.count { it.signed } shouldBe 2
        vectors.map { it.name }.toSet().size shouldBeGreaterThan 25
    }

    for (vector in vectors) {
        test("v${vector.version}${if (vector.signed) " signed" else ""} ${vector.name} #${vector.line} matches pymavlink") {
            val frames = FrameDecoder(codec).decodeAll(vector.wire)
            frames shouldHaveSize 1
            val frame = frames.single()
            frame.version shouldBe vector.version
            frame.systemId shouldBe vector.systemId
            frame.componentId shouldBe vector.componentId
            frame.sequence shouldBe vector.sequence

            val messageClass = dialect.resolve(frame.messageId) as Class<*>
            messageClass.simpleName shouldBe vector.name.split('_').joinToString("") { it.lowercase().replaceFirstChar(Char::uppercase) }
            val expected = TestMessages.build(messageClass, vector.typedValues(messageClass))

            codec.decode(frame) shouldBe expected
            if (vector.signed) {
                frame.signature?.toHex() shouldBe vector.wire.copyOfRange(vector.wire.size - 13, vector.wire.size).toHex()
                encoder.encode(frame).toHex() shouldBe vector.hex
            } else {
                frame.signature shouldBe null
                encoder.encode(expected, vector.systemId, vector.componentId, vector.sequence, vector.version).toHex() shouldBe vector.hex
                encoder.encode(frame).toHex() shouldBe vector.hex
            }
        }
    }

    test("every message both libraries know has pymavlink's CRC_EXTRA and base payload length") {
        val layouts = resourceLines("/vectors/pymavlink-messages.tsv").map { it.second.split('\t') }
        var compared = 0
        val lengthDifferences = mutableListOf<String>()
        for ((id, name, crcExtra, baseLength, fullLength) in layouts) {
            val plan = codec.planOf(id.toInt()) ?: continue
            withClue("$name ($id)") {
                plan.crcExtra shouldBe crcExtra.toInt()
                plan.baseLength shouldBe baseLength.toInt()
            }
            if (plan.length != fullLength.toInt()) lengthDifferences += "$name ${plan.length}/$fullLength"
            compared++
        }
        compared shouldBeGreaterThan 250
        // Extension fields differ where the two libraries took the XML at different times; list them
        // so a dialect upgrade shows what changed.
        println("Extension lengths that differ (io.dronefleet/pymavlink): $lengthDifferences")
    }
})

/** One line of pymavlink-vectors.tsv. */
private class Vector(
    val line: Int,
    val version: Int,
    val systemId: Int,
    val componentId: Int,
    val sequence: Int,
    val name: String,
    val fields: Map<String, JsonElement>,
    val hex: String,
) {
    val wire: ByteArray = hex.hexToBytes()
    val signed: Boolean get() = version == 2 && (wire[2].toInt() and 1) != 0

    /** The JSON values converted to the Java types of [messageClass]'s fields, keyed by camelCase name. */
    fun typedValues(messageClass: Class<*>): Map<String, Any?> {
        val fieldsByName = TestMessages.fields(messageClass).associateBy { it.name }
        val values = HashMap<String, Any?>()
        for ((snakeName, json) in fields) {
            val name = snakeName.split('_').mapIndexed { i, part -> if (i == 0) part else part.replaceFirstChar(Char::uppercase) }.joinToString("")
            val field = fieldsByName[name]
            if (field == null) {
                // A field pymavlink has and io.dronefleet lacks: only usable if zero (then truncated away).
                withClue("$name is unknown to io.dronefleet and must be zero in the vector") { isZero(json) shouldBe true }
                continue
            }
            values[name] = convert(field, json)
        }
        return values
    }

    private fun isZero(json: JsonElement): Boolean = when (json) {
        is JsonArray -> json.all { isZero(it) }
        is JsonPrimitive -> if (json.isString) json.content.isEmpty() else json.content.toDouble() == 0.0
        else -> false
    }

    private fun convert(field: TestMessages.Field, json: JsonElement): Any = when (val type = field.type) {
        Int::class.javaPrimitiveType -> number(json).toInt()
        Long::class.javaPrimitiveType -> number(json).toLong()
        Float::class.javaPrimitiveType -> number(json).toDouble().toFloat()
        Double::class.javaPrimitiveType -> number(json).toDouble()
        BigInteger::class.java -> BigInteger(number(json))
        String::class.java -> json.jsonPrimitive.also { require(it.isString) { "${field.name}: not a string: $it" } }.content
        ByteArray::class.java -> json.jsonArray.map { number(it).toInt().toByte() }.toByteArray()
        is ParameterizedType -> if (type.rawType == EnumValue::class.java) {
            TestMessages.enumValue(field, number(json).toLong().toInt())
        } else {
            json.jsonArray.map {
                when (type.actualTypeArguments[0]) {
                    Int::class.javaObjectType -> number(it).toInt()
                    Long::class.javaObjectType -> number(it).toLong()
                    Float::class.javaObjectType -> number(it).toDouble().toFloat()
                    else -> number(it).toDouble()
                }
            }
        }
        else -> error("unsupported ${type.typeName}")
    }

    /** A JSON number exactly as written, so that each field converts it exactly to its own type. */
    private fun number(json: JsonElement): String = json.jsonPrimitive.also { require(!it.isString) { "not a number: $it" } }.content

    companion object {
        fun parse(numbered: Pair<Int, String>): Vector {
            val (line, text) = numbered
            val columns = text.split('\t')
            require(columns.size == 7) { "line $line: expected 7 columns, got ${columns.size}" }
            return Vector(
                line = line,
                version = columns[0].toInt(),
                systemId = columns[1].toInt(),
                componentId = columns[2].toInt(),
                sequence = columns[3].toInt(),
                name = columns[4],
                fields = Json.parseToJsonElement(columns[5]).jsonObject,
                hex = columns[6],
            )
        }
    }
}

/** Non-comment lines of a test resource with their 1-based line numbers. */
private fun resourceLines(path: String): List<Pair<Int, String>> =
    (PymavlinkVectorsTest::class.java.getResource(path) ?: error("missing resource $path"))
        .readText(Charsets.UTF_8)
        .lines()
        .mapIndexed { index, line -> index + 1 to line }
        .filter { (_, line) -> line.isNotBlank() && !line.startsWith("#") }
