package pod.cli.gcs

import io.ktor.server.response.ApplicationResponse
import io.ktor.server.response.header

/**
 * The headers every answer of the ground station carries, because the page can command vehicles:
 * - no other site may frame it (`frame-ancestors 'none'`, X-Frame-Options): a page elsewhere
 *   could otherwise lay it under its own buttons and have the operator click "arm" (clickjacking);
 * - scripts only from the page's own files (`script-src 'self'`, no inline script or handler): a
 *   vehicle's STATUSTEXT or a dropped plan's text that reached the DOM unescaped cannot run;
 * - images from anywhere (the `--tiles` server), connections only back to this server;
 * - no Referer (the page's URL may hold the token), no content sniffing, no caching.
 */
internal object GcsHeaders {
    const val CONTENT_SECURITY_POLICY: String =
        "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data: blob: http: https:; " +
            "connect-src 'self'; object-src 'none'; base-uri 'none'; form-action 'self'; frame-ancestors 'none'"

    fun secure(response: ApplicationResponse) {
        response.header("Content-Security-Policy", CONTENT_SECURITY_POLICY)
        response.header("X-Frame-Options", "DENY")
        response.header("X-Content-Type-Options", "nosniff")
        response.header("Referrer-Policy", "no-referrer")
        response.header("Cache-Control", "no-store")
    }
}
