package pod.cli.gcs

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll

class HttpAddressTest : StringSpec({
    "HOST:PORT, a bracketed IPv6 host and port 0 are read" {
        HttpAddress.parse("127.0.0.1:8080") shouldBe HttpAddress("127.0.0.1", 8080)
        HttpAddress.parse("0.0.0.0:0") shouldBe HttpAddress("0.0.0.0", 0)
        HttpAddress.parse("localhost:65535") shouldBe HttpAddress("localhost", 65535)
        HttpAddress.parse("[::1]:8080") shouldBe HttpAddress("::1", 8080)
        HttpAddress.parse("[::]:0") shouldBe HttpAddress("::", 0)
    }

    "anything else is refused" {
        for (text in listOf("", "8080", "localhost", ":8080", "host:", "host:x", "host:-1", "host:65536", "::1:8080", "[]:80", "host:80:80")) {
            withClue(text) { HttpAddress.parse(text).shouldBeNull() }
        }
    }

    "every port in range goes through and every other is refused" {
        checkAll(Arb.int(-100_000..200_000)) { port ->
            HttpAddress.parse("127.0.0.1:$port")?.port shouldBe port.takeIf { it in 0..65535 }
        }
    }
})
