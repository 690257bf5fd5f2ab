package pod.mavlink.signing

/**
 * A MAVLink 2 signing key: the 32-byte secret a ground station and its vehicles share. Its bytes
 * never leave this class except into the signature's hash; [toString] hides them, so a key in a
 * log line or an exception message says only that it is a key.
 */
public class SigningKey(bytes: ByteArray) {
    init {
        require(bytes.size == SIZE) { "a signing key is $SIZE bytes, was ${bytes.size}" }
    }

    internal val secret: ByteArray = bytes.copyOf()

    override fun equals(other: Any?): Boolean = other is SigningKey && secret.contentEquals(other.secret)

    override fun hashCode(): Int = secret.contentHashCode()

    override fun toString(): String = "SigningKey(hidden)"

    /** Makes keys from their written forms. */
    public companion object {
        /** The key's length in bytes (MAVLink 2 signing: a 32-byte secret key). */
        public const val SIZE: Int = 32

        /** The key written as 64 hexadecimal digits (whitespace ignored). */
        public fun fromHex(hex: String): SigningKey {
            val digits = hex.filterNot { it.isWhitespace() }
            require(digits.length == SIZE * 2 && digits.all { it.isDigit() || it.lowercaseChar() in 'a'..'f' }) {
                "a signing key in hex is ${SIZE * 2} hexadecimal digits"
            }
            return SigningKey(ByteArray(SIZE) { digits.substring(it * 2, it * 2 + 2).toInt(16).toByte() })
        }
    }
}
