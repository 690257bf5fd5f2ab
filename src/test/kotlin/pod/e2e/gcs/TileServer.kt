package pod.e2e.gcs

import com.sun.net.httpserver.HttpServer
import java.awt.Color
import java.awt.image.BufferedImage
import java.io.ByteArrayOutputStream
import java.net.InetAddress
import java.net.InetSocketAddress
import java.util.concurrent.ConcurrentLinkedQueue
import javax.imageio.ImageIO

/**
 * A map tile server for tests, on loopback: every path gets the same 256 px PNG (pale, with a
 * border, so a screenshot shows where the tiles lie) and is recorded in [paths], in order.
 */
internal class TileServer : AutoCloseable {
    /** The paths asked for, oldest first. */
    val paths = ConcurrentLinkedQueue<String>()

    private val png: ByteArray = ByteArrayOutputStream().also { out ->
        val image = BufferedImage(256, 256, BufferedImage.TYPE_INT_RGB)
        val g = image.createGraphics()
        g.color = Color(0xEA, 0xF1, 0xE4)
        g.fillRect(0, 0, 256, 256)
        g.color = Color(0x9C, 0xB4, 0x8C)
        g.drawRect(0, 0, 255, 255)
        g.dispose()
        ImageIO.write(image, "png", out)
    }.toByteArray()

    private val server = HttpServer.create(InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 0).apply {
        createContext("/") { exchange ->
            paths += exchange.requestURI.path
            exchange.responseHeaders.add("Content-Type", "image/png")
            exchange.sendResponseHeaders(200, png.size.toLong())
            exchange.responseBody.use { it.write(png) }
        }
        start()
    }

    /** The `--tiles` template pointing here. */
    val template: String get() = "http://127.0.0.1:${server.address.port}/tiles/{z}/{x}/{y}.png"

    /** The `z/x/y` of each tile asked for. */
    fun tiles(): List<Tile> = paths.mapNotNull { path ->
        Regex("""^/tiles/(\d+)/(\d+)/(\d+)\.png$""").find(path)?.destructured?.let { (z, x, y) -> Tile(z.toInt(), x.toInt(), y.toInt()) }
    }

    override fun close() = server.stop(0)
}

/** An XYZ tile's numbers. */
internal data class Tile(val z: Int, val x: Int, val y: Int)
