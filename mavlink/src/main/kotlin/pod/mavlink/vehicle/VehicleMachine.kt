package pod.mavlink.vehicle

import pod.mavlink.protocol.Step

/**
 * One microservice as the vehicle speaks it, as a pure state machine: feed it what a ground
 * station sends and the expiry of the timer it asked for, each with the clock reading in
 * nanoseconds, and do what each [Step] says. [serve] is its driver.
 *
 * Package `pod.mavlink.vehicle` is the vehicle side of MAVLink's microservices, for simulators
 * and companion computers that answer a ground station rather than command a vehicle: this
 * contract and its driver ([serve]), the mission server ([MissionServer]), how mission messages
 * are read and answered ([MissionFrames]) and how a vehicle numbers the frames it sends
 * ([VehicleEncoder]). Pod's simulator (pod-sim) is built on it; the ground side lives in the
 * rest of pod-mavlink.
 *
 * It is the vehicle-side twin of the ground side's protocol machines (start / onMessage /
 * onTimer, driven by `MavlinkVehicle.run`), with the same [Step]s, and differs where a server
 * differs from a client: it has no `start` (it speaks only when spoken to, or when its own timer
 * says so) and its steps carry no outcome (it serves for as long as the vehicle runs; a
 * transfer that ends is state inside it, not the end of the machine). Replies go to whoever sent
 * the message they answer; a timer's messages go to the last one who spoke.
 *
 * [I] is what it reads (already decoded and addressed to this vehicle), [O] what it sends.
 */
public interface VehicleMachine<in I, out O> {
    /** [message] arrived at [now]: what to send back to its sender, and when to wake next. */
    public fun onMessage(message: I, now: Long): Step<O, Nothing>

    /** The timer set by an earlier step expired; [now] is at or after its wake time. */
    public fun onTimer(now: Long): Step<O, Nothing>
}
