package pod.mavlink.param

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe

class ParamTypeTest : StringSpec({
    "an integer parameter stores a fraction rounded half away from zero; a float keeps it as a float" {
        ParamType.INT8.stored(2.7) shouldBe 3.0
        ParamType.INT8.stored(2.5) shouldBe 3.0
        ParamType.INT16.stored(-2.5) shouldBe -3.0
        ParamType.INT32.stored(-0.4) shouldBe 0.0
        ParamType.REAL32.stored(0.1) shouldBe 0.1f.toDouble()
    }

    "an integer type's own range is known; a value outside it is refused with the range named" {
        ParamType.INT8.range shouldBe -128.0..127.0
        ParamType.UINT8.range shouldBe 0.0..255.0
        ParamType.REAL32.range shouldBe null
        ParamOutOfRange("DISARM_DELAY", ParamType.INT8, 300.0, ParamType.INT8.range!!).message shouldBe
            "DISARM_DELAY is an integer parameter (INT8) holding -128..127: 300 does not fit"
        ParamRejected("COM_DISARM_PRFLT", 300.0, 10.0).message shouldBe
            "the vehicle kept COM_DISARM_PRFLT = 10 instead of 300 (read-only, out of its range, or refused)"
    }
})
