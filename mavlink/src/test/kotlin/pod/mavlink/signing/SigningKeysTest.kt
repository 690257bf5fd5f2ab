package pod.mavlink.signing

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.attribute.PosixFilePermissions

private const val HEX = "000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f"

private fun keyFile(content: ByteArray, mode: String = "rw-------"): Path {
    val file = Files.createTempFile("pod-key", ".key")
    Files.write(file, content)
    Files.setPosixFilePermissions(file, PosixFilePermissions.fromString(mode))
    return file
}

class SigningKeysTest : StringSpec({

    "a key file holds 32 raw bytes or 64 hex digits (a final newline ignored); the environment variable 64 hex digits" {
        val expected = SigningKey.fromHex(HEX)
        SigningKeys.fromFile(keyFile(ByteArray(32) { it.toByte() })) shouldBe expected
        SigningKeys.fromFile(keyFile("$HEX\n".toByteArray())) shouldBe expected
        SigningKeys.resolve(null, mapOf(SigningKeys.ENVIRONMENT_VARIABLE to HEX.uppercase())) shouldBe expected
        SigningKeys.resolve(null, emptyMap()) shouldBe null
        SigningKeys.resolve(keyFile(ByteArray(32) { it.toByte() }), mapOf(SigningKeys.ENVIRONMENT_VARIABLE to "zz")) shouldBe expected
    }

    "malformed, missing or open key files are typed errors that name the file and never show the key" {
        val secretish = HEX.substring(0, 40)
        val short = shouldThrow<InvalidSigningKey> { SigningKeys.fromFile(keyFile(secretish.toByteArray())) }
        short.reason shouldContain "32 raw bytes or 64 hexadecimal digits"
        short.message!! shouldNotContain secretish.substring(0, 8)
        val open = shouldThrow<InvalidSigningKey> { SigningKeys.fromFile(keyFile("$HEX\n".toByteArray(), "rw-r--r--")) }
        open.reason shouldContain "chmod 600"
        open.message!! shouldNotContain HEX.substring(0, 8)
        shouldThrow<InvalidSigningKey> { SigningKeys.fromFile(Path.of("/nonexistent/pod.key")) }.reason shouldBe "no such file"
        val env = shouldThrow<InvalidSigningKey> { SigningKeys.resolve(null, mapOf(SigningKeys.ENVIRONMENT_VARIABLE to "${HEX}00")) }
        env.source shouldBe "\$POD_SIGNING_KEY"
        env.message!! shouldNotContain HEX.substring(0, 8)
    }

    "a policy and a station config print without the key" {
        val policy = LinkSigning(SigningKey.fromHex(HEX), linkId = 2)
        policy.toString() shouldNotContain "0001"
        pod.mavlink.GroundStationConfig(signing = policy).toString() shouldNotContain "0001020304"
        shouldThrow<IllegalArgumentException> { pod.mavlink.GroundStationConfig(mavlinkVersion = 1, signing = policy) }
    }
})
