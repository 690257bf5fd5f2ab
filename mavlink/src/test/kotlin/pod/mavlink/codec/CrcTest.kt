package pod.mavlink.codec

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe

internal class CrcTest : StringSpec({
    "CRC-16/MCRF4XX of the standard check string is 0x6F91" {
        val check = "123456789".toByteArray()
        Crc.accumulate(Crc.INITIAL, check, 0, check.size) shouldBe 0x6F91
    }

    "the frame checksum covers the given range and then CRC_EXTRA" {
        val bytes = byteArrayOf(0x55, 1, 2, 3, 0x66)
        val expected = Crc.accumulate(Crc.accumulate(Crc.INITIAL, byteArrayOf(1, 2, 3), 0, 3), 50)
        Crc.frameChecksum(bytes, 1, 3, 50) shouldBe expected
        Crc.accumulate(Crc.INITIAL, byteArrayOf(), 0, 0) shouldBe Crc.INITIAL
    }
})
