package pod.e2e.gcs

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.ints.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.runBlocking
import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.floor
import kotlin.math.ln
import kotlin.math.log2
import kotlin.math.roundToInt
import kotlin.math.tan

/** `pod gcs --tiles URL-template`: XYZ tiles under the grid, the ones the view needs, lined up with the vehicles. */
class GcsTilesSpec : StringSpec({

    "with --tiles the page fetches the tiles holding the fleet at the zoom fitting the scale, lined up with the markers" {
        TileServer().use { tiles ->
            runBlocking {
                GcsFixture.start(count = 1, timeScale = 5.0, tiles = tiles.template).use { gcs ->
                    GcsBrowser().use { browser ->
                        browser.open(gcs.url)
                        val marker = browser.await("vehicle 1's marker") { MapProbe.marker(browser, 1) }
                        val home = gcs.sim[1].config.home

                        val ppm = (browser.js("return pod.map.pixelsPerMetre()") as Number).toDouble()
                        val z = zoomFor(ppm, home.latitude)
                        val holding = tileOf(home.latitude, home.longitude, z)
                        browser.awaitTrue("the tile $holding asked for") { holding in tiles.tiles() }
                        tiles.tiles().distinct().size shouldBeLessThanOrEqual 48
                        tiles.tiles().map { it.z }.distinct() shouldBe listOf(z)

                        // The vehicle sits in its tile where Web Mercator puts it: the tile was placed by its corners.
                        val box = browser.js(
                            """const img = document.querySelector(`#map image[data-tile="${'$'}{arguments[0]}"]`), m = document.getElementById("map").getBoundingClientRect();
                               if (!img) return null; const r = img.getBoundingClientRect(); return [r.left - m.left, r.top - m.top, r.width, r.height];""",
                            "${holding.z}/${holding.x}/${holding.y}",
                        ) as List<*>
                        val (left, top, width, height) = box.map { (it as Number).toDouble() }
                        val (fx, fy) = fractionInTile(marker.lat, marker.lon, z)
                        marker.x shouldBe (left + fx * width plusOrMinus 2.0)
                        marker.y shouldBe (top + fy * height plusOrMinus 2.0)
                        browser.find("#map-tiles-note").text shouldBe "tiles: 127.0.0.1:${tiles.template.substringAfter("127.0.0.1:").substringBefore("/")}"
                        browser.screenshot("tiles-under-the-grid")

                        // Zoomed far out: coarser tiles, still the one holding the fleet.
                        browser.js("pod.map.centreOn(arguments[0], arguments[1], 0.05)", home.latitude, home.longitude)
                        val coarse = tileOf(home.latitude, home.longitude, zoomFor(0.05, home.latitude))
                        browser.awaitTrue("the coarse tile $coarse asked for") { coarse in tiles.tiles() }
                        tiles.tiles().map { it.z }.distinct() shouldContain coarse.z
                    }
                }
            }
        }
    }
})

private const val EQUATOR_M_PER_PX_Z0 = 2 * PI * 6378137.0 / 256

/** The XYZ zoom whose pixel is closest to [ppm] pixels per metre at [lat] (at most 19). */
private fun zoomFor(ppm: Double, lat: Double): Int = log2(EQUATOR_M_PER_PX_Z0 * cos(lat * PI / 180) * ppm).roundToInt().coerceIn(0, 19)

/** The tile position of a point: x and y in tiles (fractional) at zoom [z], per the XYZ / Web Mercator scheme. */
private fun tileXY(lat: Double, lon: Double, z: Int): Pair<Double, Double> {
    val n = (1 shl z).toDouble()
    val r = lat * PI / 180
    return (lon + 180) / 360 * n to (1 - ln(tan(r) + 1 / cos(r)) / PI) / 2 * n
}

private fun tileOf(lat: Double, lon: Double, z: Int): Tile = tileXY(lat, lon, z).let { (x, y) -> Tile(z, floor(x).toInt(), floor(y).toInt()) }

private fun fractionInTile(lat: Double, lon: Double, z: Int): Pair<Double, Double> = tileXY(lat, lon, z).let { (x, y) -> (x - floor(x)) to (y - floor(y)) }
