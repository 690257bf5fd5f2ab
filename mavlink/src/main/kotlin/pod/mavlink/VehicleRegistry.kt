package pod.mavlink

import io.dronefleet.mavlink.minimal.Heartbeat
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharedFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asSharedFlow
import kotlinx.coroutines.flow.asStateFlow
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.VehicleIdentity
import pod.mavlink.codec.FrameView
import pod.mavlink.codec.MavFrame
import pod.mavlink.link.LinkPeer
import pod.mavlink.telemetry.HotFields
import pod.mavlink.telemetry.HotMessages
import kotlin.time.Duration

/**
 * The vehicles one [GroundStation] has heard, by system id: a vehicle is made from its first
 * HEARTBEAT (only a vehicle's: not a GCS, camera or gimbal), marked lost when its heartbeats stop
 * for [lostAfter] and regained by the next one; each frame of a known system goes to its vehicle.
 * Found and regained vehicles are asked for their streams ([streamRequests]).
 *
 * Written only from the station's receive path ([onMessage]) and its tracking loop
 * ([checkSilence]); see GroundStation.onBytes for what other threads may read.
 */
internal class VehicleRegistry(
    private val station: GroundStation,
    private val lostAfter: Duration,
    private val streamRequests: StreamRequests,
    private val guarded: (() -> Unit) -> Unit,
) {
    private val _vehicles = MutableStateFlow<Map<Int, MavlinkVehicle>>(emptyMap())
    private val _events = MutableSharedFlow<FleetEvent>(extraBufferCapacity = 256)
    @Volatile private var unrouted = 0L

    /** [vehicles] by system id as an array: the receive path looks a vehicle up with no boxed key. Its writer is the receive path. */
    private val bySystem = arrayOfNulls<MavlinkVehicle>(256)

    /** Where the hot messages are read into, reused for every frame (the receive path's alone). */
    private val fields = HotFields()

    /** Vehicles heard so far by system id, lost ones included. */
    val vehicles: StateFlow<Map<Int, MavlinkVehicle>> = _vehicles.asStateFlow()

    /** Found, lost and regained vehicles, as they happen. */
    val events: SharedFlow<FleetEvent> = _events.asSharedFlow()

    /** Frames from systems that never sent a vehicle HEARTBEAT (not routed). */
    val unroutedFrames: Long get() = unrouted

    /** Routes [message] (decoded from [frame], null when unknown), heard from [peer], to its vehicle. */
    fun onMessage(peer: LinkPeer, frame: MavFrame, message: Any?) {
        val vehicle = bySystem[frame.systemId]
        if (message is Heartbeat) {
            val type = message.type().value()
            val autopilot = message.autopilot().value()
            if (vehicle == null && MavlinkEnums.isVehicle(type, autopilot)) {
                found(peer, frame, message, VehicleIdentity(frame.systemId, frame.componentId, MavlinkEnums.vehicleType(type), MavlinkEnums.autopilot(autopilot)))
                return
            }
            if (vehicle != null && frame.componentId == vehicle.identity.value.componentId && vehicle._connection.value == ConnectionState.LOST) {
                regain(vehicle, peer, frame, message)
                return
            }
        }
        if (vehicle == null) {
            unrouted++
            return
        }
        vehicle.peer = peer
        vehicle.onFrame(frame, message)
    }

    /**
     * Routes a hot telemetry message ([HotMessages]) read in place from [view], allocating
     * nothing; false when it needs [onMessage] instead (a vehicle to find or regain, or one whose
     * frames someone wants as objects), and then the caller decodes it and calls that.
     */
    fun onHotFrame(peer: LinkPeer, view: FrameView): Boolean {
        val vehicle = bySystem[view.systemId]
        val heartbeat = view.messageId == MessageIds.HEARTBEAT
        if (vehicle == null) {
            // Only a vehicle's heartbeat makes a vehicle; anything else from an unknown system is counted.
            if (heartbeat && MavlinkEnums.isVehicle(view.u8(HEARTBEAT_TYPE), view.u8(HEARTBEAT_AUTOPILOT))) return false
            unrouted++
            return true
        }
        if (vehicle.wantsObjects) return false
        if (heartbeat && view.componentId == vehicle.identity.value.componentId && vehicle._connection.value == ConnectionState.LOST) return false
        vehicle.peer = peer
        vehicle.onHotFrame(view, fields)
        return true
    }

    private fun found(peer: LinkPeer, frame: MavFrame, heartbeat: Heartbeat, identity: VehicleIdentity) {
        val vehicle = MavlinkVehicle(identity, station)
        vehicle.peer = peer
        // Its first heartbeat is applied before anyone can see the vehicle: a caller that
        // picks it from [vehicles] at once reads its armed state and mode, not defaults.
        vehicle.onFrame(frame, heartbeat)
        bySystem[frame.systemId] = vehicle
        _vehicles.value = _vehicles.value + (frame.systemId to vehicle)
        _events.tryEmit(FleetEvent.Found(vehicle))
        streamRequests.restart(vehicle)
    }

    private fun regain(vehicle: MavlinkVehicle, peer: LinkPeer, frame: MavFrame, heartbeat: Heartbeat) {
        // The frame (a heartbeat refreshes lastHeartbeat) and the turn to CONNECTED under the
        // lock checkSilence reads them under: it never sees the vehicle regained with its
        // old heartbeat time, which would mark it lost again at once.
        val regained = synchronized(vehicle.connectionLock) {
            vehicle.peer = peer
            vehicle.onFrame(frame, heartbeat)
            vehicle._connection.compareAndSet(ConnectionState.LOST, ConnectionState.CONNECTED)
        }
        if (regained) {
            _events.tryEmit(FleetEvent.Regained(vehicle))
            streamRequests.restart(vehicle)
        }
    }

    /** Marks lost every vehicle silent for longer than [lostAfter]; flushes overdue status texts on the way. */
    fun checkSilence() {
        for (vehicle in _vehicles.value.values) {
            guarded { vehicle.flushStatusTexts() }
            val silence = vehicle.lastHeartbeat.elapsedNow()
            if (silence > lostAfter && synchronized(vehicle.connectionLock) {
                    vehicle.lastHeartbeat.elapsedNow() > lostAfter &&
                        vehicle._connection.compareAndSet(ConnectionState.CONNECTED, ConnectionState.LOST)
                }
            ) {
                guarded { vehicle.markedLost() }
                _events.tryEmit(FleetEvent.Lost(vehicle, silence))
            }
        }
    }

    private companion object {
        /** Offsets of HEARTBEAT's type and autopilot in its payload (minimal.xml wire order). */
        const val HEARTBEAT_TYPE = 4
        const val HEARTBEAT_AUTOPILOT = 5
    }
}
