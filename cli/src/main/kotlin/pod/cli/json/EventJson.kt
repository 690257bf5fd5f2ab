package pod.cli.json

import kotlinx.serialization.KSerializer
import kotlinx.serialization.Serializable
import kotlinx.serialization.descriptors.PrimitiveKind
import kotlinx.serialization.descriptors.PrimitiveSerialDescriptor
import kotlinx.serialization.descriptors.SerialDescriptor
import kotlinx.serialization.encoding.Decoder
import kotlinx.serialization.encoding.Encoder
import kotlinx.serialization.json.Json

/** Reads and writes [Event] lines: one JSON object per line, its kind in the `event` field. */
public object EventJson {
    private val json = Json {
        classDiscriminator = "event"
        // Every field on every line, so a reader never has to guess whether a missing one means null.
        encodeDefaults = true
        explicitNulls = true
    }

    /** [event] as one line of JSON (no newline). */
    public fun encode(event: Event): String = json.encodeToString(Event.serializer(), event)

    /**
     * The event on [line]; throws [kotlinx.serialization.SerializationException] (an
     * [IllegalArgumentException]) when it is not one: unknown kind, unknown or missing field.
     */
    public fun decode(line: String): Event = json.decodeFromString(Event.serializer(), line)
}

/** A Double written as a JSON number when finite and as `null` when not (NaN, ±Infinity): JSON has no such numbers. */
public typealias Finite = @Serializable(with = FiniteDoubleSerializer::class) Double

/** Serializer of [Finite]: non-finite values become `null` (the property must be nullable to read them back). */
public object FiniteDoubleSerializer : KSerializer<Double> {
    override val descriptor: SerialDescriptor = PrimitiveSerialDescriptor("pod.cli.json.Finite", PrimitiveKind.DOUBLE)

    @OptIn(kotlinx.serialization.ExperimentalSerializationApi::class)
    override fun serialize(encoder: Encoder, value: Double) {
        if (value.isFinite()) encoder.encodeDouble(value) else encoder.encodeNull()
    }

    override fun deserialize(decoder: Decoder): Double = decoder.decodeDouble()
}
