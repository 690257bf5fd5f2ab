package pod.e2e.gcs

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe

/** `pod gcs` in a real browser: the page and its live fleet. */
class GcsPageSpec : StringSpec({

    "the page loads, connects and lists every simulated vehicle in the fleet table and on the map" {
        withGcs(count = 3) { gcs, browser ->
            browser.open(gcs.url)
            browser.awaitTrue("three fleet rows") { browser.findAll("#fleet tbody tr").size == 3 }
            browser.findAll("#fleet tbody tr").map { it.getAttribute("data-sysid") } shouldBe listOf("1", "2", "3")
            browser.awaitTrue("three vehicle markers") { browser.findAll("#map g.vehicle").size == 3 }
            browser.find("#connection").text shouldBe "connected"
            browser.screenshot("fleet")
        }
    }
})
