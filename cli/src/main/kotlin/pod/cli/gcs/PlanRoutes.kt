package pod.cli.gcs

import io.ktor.http.ContentDisposition
import io.ktor.http.ContentType
import io.ktor.http.HttpHeaders
import io.ktor.http.HttpStatusCode
import io.ktor.server.response.header
import io.ktor.server.response.respondText
import io.ktor.server.routing.Route
import io.ktor.server.routing.get
import kotlinx.coroutines.async
import pod.core.PodException
import pod.mavlink.plan.QgcPlanFile

/**
 * `GET /api/vehicles/{sysid}/plan`: vehicle `sysid`'s mission, fence and rally points as a QGC
 * .plan file (an attachment named `vehicle-SYSID.plan`), as `pod mission download x.plan` writes
 * it. Behind the server's access checks like every route. A vehicle not on the link is 404; one
 * that refuses or does not answer is 502, with its words as the text.
 */
internal fun Route.planRoutes(fleet: GcsFleet) {
    get("/api/vehicles/{sysid}/plan") {
        val sysid = call.parameters["sysid"]?.toIntOrNull()?.takeIf { it in 1..255 }
        if (sysid == null) {
            call.respondText("the vehicle must be a system id in 1..255, was '${call.parameters["sysid"]}'", status = HttpStatusCode.BadRequest)
            return@get
        }
        if (fleet.station.vehicles.value[sysid] == null) {
            call.respondText("no vehicle $sysid on ${fleet.station.link.address}", status = HttpStatusCode.NotFound)
            return@get
        }
        val plan = try {
            // Run in the fleet's scope, like a page's request: a page closed half-way does not cut a transfer short.
            fleet.scope.async { fleet.service(PlanDesk::class) { PlanDesk(it) }.download(sysid) }.await()
        } catch (e: GcsRequestException) {
            call.respondText(e.message ?: "refused", status = HttpStatusCode.Conflict)
            return@get
        } catch (e: PodException) {
            call.respondText("vehicle $sysid: ${e.message}", status = HttpStatusCode.BadGateway)
            return@get
        }
        call.response.header(HttpHeaders.ContentDisposition, ContentDisposition.Attachment.withParameter(ContentDisposition.Parameters.FileName, "vehicle-$sysid.plan").toString())
        call.respondText(QgcPlanFile.write(plan), ContentType.Application.Json)
    }
}
