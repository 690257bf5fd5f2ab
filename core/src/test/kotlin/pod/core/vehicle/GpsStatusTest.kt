package pod.core.vehicle

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe

class GpsStatusTest : StringSpec({
    "GPS_RAW_INT fix types read by name; a number outside GPS_FIX_TYPE is no fix type, not a 3D fix" {
        GpsStatus(3, 10).fix shouldBe GpsFix.FIX_3D
        GpsStatus(6, 10).fix shouldBe GpsFix.RTK_FIXED
        GpsStatus(8, 10).fix shouldBe GpsFix.PPP
        GpsStatus(0, null).fix shouldBe GpsFix.NO_GPS
        GpsStatus(255, 10).fix shouldBe null
        GpsStatus(255, 10).has3dFix shouldBe false
        GpsStatus(3, 10).has3dFix shouldBe true
        GpsStatus(2, 10).has3dFix shouldBe false
    }
})
