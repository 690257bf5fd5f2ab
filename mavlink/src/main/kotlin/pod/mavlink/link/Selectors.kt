package pod.mavlink.link

import io.ktor.network.selector.SelectorManager
import kotlinx.coroutines.Dispatchers

/**
 * The one Ktor selector every TCP link of this process registers its socket with (UDP links use
 * java.nio directly, see [UdpLink]). A selector parks a
 * Dispatchers.IO thread in `select()`; one per link exhausted the 64 IO threads at about 60 links
 * (a `SimFleet` of 100 answered commands in a median 500 ms, a third of them resent). One
 * selector serves any number of sockets. It lives as long as the process; closing a link closes
 * only its socket.
 */
internal object Selectors {
    val shared: SelectorManager by lazy { SelectorManager(Dispatchers.IO) }
}
