"""MAVSDK 4 as the ground station flying a vehicle with its Action, Param and Telemetry plugins.

Usage: mavsdk_action.py LISTEN_PORT SECONDS flight ALTITUDE CRUISE NORTH_M
       mavsdk_action.py LISTEN_PORT SECONDS arm

Listens with udpin://127.0.0.1:LISTEN_PORT and takes the first autopilot that sends a heartbeat
there. Both scenarios first wait until Telemetry has a position, a home position and a 3D GPS fix
(not Telemetry.health(): see "ready" below), then:

flight: reads and writes parameters with the Param plugin (MPC_XY_CRUISE := CRUISE and
    COM_DISARM_PRFLT := -1 as floats, NAV_DLL_ACT := 2 as an int, MAV_SYS_ID and SYS_AUTOSTART read
    as ints, and MPC_XY_CRUISE read as an int, which MAVSDK refuses), then
    Action.set_takeoff_altitude(ALTITUDE), arm(), takeoff() until the relative altitude reaches
    ALTITUDE, goto_location() NORTH_M metres north of home at the same height until within 1.5 m,
    land() until Telemetry says on the ground and disarmed.
arm: Action.arm() once, and reports the result and the status texts that came with it.

Prints one JSON object per line on stdout:
    {"event": "ready", "version": ..}                        MAVSDK is listening
    {"event": "system", "sysid": .., "autopilot": "PX4", "vehicle": ..}
    {"event": "position", "fix": "FIX_3D", "satellites": .., "home_amsl": .., "health_*": ..}
    {"event": "param", "op": "get"|"set", "name": .., "kind": "int"|"float", "result": "SUCCESS", "value": ..}
    {"event": "action", "step": "arm", "result": "SUCCESS"|"COMMAND_DENIED"|..}   one per Action call
    {"event": "armed"} / {"event": "altitude", "relative_m": ..} / {"event": "arrived", ..}
    {"event": "landed", "in_air": false, "armed": false, "landed_state": "ON_GROUND"}
    {"event": "status_text", "type": "CRITICAL", "text": ..}  every STATUSTEXT MAVSDK passes on
    {"event": "checkpoint", "name": ..}                      then waits for a line on stdin
    {"event": "done"}
A failed Action call ends the flight scenario (exit 1). At a checkpoint the script reads one line
from stdin before it goes on, so the test can look at the vehicle in a known state. The whole run
is bounded by SECONDS (exit 3 when they pass). Loopback only.
"""
import math
import os
import sys
import threading
import time

from mavsdk_peer_io import emit, listen, start_watchdog
from mavsdk import ComponentType, Configuration, Mavsdk
from mavsdk.plugins.action import Action, ActionError, ActionResult
from mavsdk.plugins.param import Param, ParamError
from mavsdk.plugins.telemetry import Telemetry

EARTH_RADIUS_M = 6_371_000.0


class Latest:
    """The latest value a Telemetry subscription delivered, and a bounded wait for a condition on it."""

    def __init__(self) -> None:
        self._value = None
        self._changed = threading.Condition()

    def update(self, value, _user_data=None) -> None:
        with self._changed:
            self._value = value
            self._changed.notify_all()

    def wait(self, predicate, timeout: float, what: str):
        deadline = time.monotonic() + timeout
        with self._changed:
            while self._value is None or not predicate(self._value):
                left = deadline - time.monotonic()
                if left <= 0:
                    raise TimeoutError(f"{what}: last value {self._value}")
                self._changed.wait(left)
            return self._value


def checkpoint(name: str) -> None:
    emit({"event": "checkpoint", "name": name})
    if not sys.stdin.readline():
        emit({"event": "error", "what": f"stdin closed at checkpoint {name}"})
        os._exit(4)


def act(step: str, call, *args) -> bool:
    try:
        call(*args)
    except ActionError as e:
        emit({"event": "action", "step": step, "result": e.result.name})
        return False
    emit({"event": "action", "step": step, "result": ActionResult.SUCCESS.name})
    return True


def param(op: str, kind: str, name: str, call, *args) -> None:
    try:
        value = call(name, *args)
        if op == "set":
            value = args[0]
        emit({"event": "param", "op": op, "name": name, "kind": kind, "result": "SUCCESS", "value": value})
    except ParamError as e:
        emit({"event": "param", "op": op, "name": name, "kind": kind, "result": e.result.name})


def offset_north(lat: float, lon: float, metres: float):
    return lat + math.degrees(metres / EARTH_RADIUS_M), lon


def horizontal_distance(lat1, lon1, lat2, lon2) -> float:
    north = math.radians(lat2 - lat1) * EARTH_RADIUS_M
    east = math.radians(lon2 - lon1) * EARTH_RADIUS_M * math.cos(math.radians(lat1))
    return math.hypot(north, east)


def fly(system, telemetry, streams, altitude: float, cruise: float, north: float, home) -> int:
    params = Param(system)
    param("get", "float", "MPC_XY_CRUISE", params.get_param_float)
    param("set", "float", "MPC_XY_CRUISE", params.set_param_float, cruise)
    param("get", "float", "MPC_XY_CRUISE", params.get_param_float)
    param("set", "float", "COM_DISARM_PRFLT", params.set_param_float, -1.0)
    param("get", "int", "MAV_SYS_ID", params.get_param_int)
    param("get", "int", "SYS_AUTOSTART", params.get_param_int)
    param("set", "int", "NAV_DLL_ACT", params.set_param_int, 2)
    param("get", "int", "NAV_DLL_ACT", params.get_param_int)
    param("get", "int", "MPC_XY_CRUISE", params.get_param_int)
    checkpoint("params")

    action = Action(system)
    if not act("set_takeoff_altitude", action.set_takeoff_altitude, altitude):
        return 1
    if not act("arm", action.arm):
        return 1
    streams["armed"].wait(lambda armed: armed, 5, "armed")
    emit({"event": "armed"})
    checkpoint("armed")

    if not act("takeoff", action.takeoff):
        return 1
    reached = streams["position"].wait(lambda p: p.relative_altitude_m >= altitude - 0.3, 15, "takeoff altitude")
    emit({"event": "altitude", "relative_m": reached.relative_altitude_m})
    checkpoint("altitude")

    lat, lon = offset_north(home.latitude_deg, home.longitude_deg, north)
    if not act("goto_location", action.goto_location, lat, lon, home.absolute_altitude_m + altitude, 0.0):
        return 1
    there = streams["position"].wait(
        lambda p: horizontal_distance(p.latitude_deg, p.longitude_deg, lat, lon) < 1.5, 20, "goto arrival")
    emit({"event": "arrived", "latitude_deg": there.latitude_deg, "longitude_deg": there.longitude_deg,
          "relative_m": there.relative_altitude_m, "target_latitude_deg": lat, "target_longitude_deg": lon})
    checkpoint("arrived")

    if not act("land", action.land):
        return 1
    streams["in_air"].wait(lambda in_air: not in_air, 30, "on the ground")
    streams["armed"].wait(lambda armed: not armed, 15, "disarmed")
    emit({"event": "landed", "in_air": telemetry.in_air(), "armed": telemetry.armed(),
          "landed_state": telemetry.landed_state().name})
    return 0


def arm_once(system, texts: Latest) -> int:
    action = Action(system)
    started = time.monotonic()
    act("arm", action.arm)
    # PX4 sends its reason just before the ack; give a late one a moment, no more.
    try:
        texts.wait(lambda t: True, 2, "status text")
    except TimeoutError:
        pass
    emit({"event": "arm_done", "seconds": round(time.monotonic() - started, 3)})
    return 0


def main() -> int:
    port, seconds, scenario = int(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
    start_watchdog(seconds)
    mavsdk = Mavsdk(Configuration.create_with_component_type(ComponentType.GROUND_STATION))
    try:
        if not listen(mavsdk, port):
            return 2
        system = mavsdk.first_autopilot(timeout_s=seconds)
        if system is None:
            emit({"event": "error", "what": "no autopilot heard"})
            return 2
        emit({"event": "system", "sysid": system.get_system_id(), "autopilot": system.autopilot_type().name,
              "vehicle": system.vehicle_type().name})

        telemetry = Telemetry(system)
        streams = {name: Latest() for name in ("position", "home", "gps", "armed", "in_air", "health")}
        texts = Latest()
        telemetry.subscribe_position(streams["position"].update)
        telemetry.subscribe_home(streams["home"].update)
        telemetry.subscribe_gps_info(streams["gps"].update)
        telemetry.subscribe_armed(streams["armed"].update)
        telemetry.subscribe_in_air(streams["in_air"].update)
        telemetry.subscribe_health(streams["health"].update)

        def on_text(text, _user_data):
            emit({"event": "status_text", "type": text.type.name, "text": text.text})
            texts.update(text)

        telemetry.subscribe_status_text(on_text)

        # What MAVSDK's own examples wait for: global position and home OK (from SYS_STATUS sensor
        # bits and HOME_POSITION).
        streams["position"].wait(lambda p: not math.isnan(p.latitude_deg), 10, "position")
        home = streams["home"].wait(lambda h: not math.isnan(h.latitude_deg), 10, "home position")
        gps = streams["gps"].wait(lambda g: g.fix_type.name in ("FIX_3D", "FIX_DGPS", "RTK_FLOAT", "RTK_FIXED"), 10, "3D fix")
        health = streams["health"].wait(lambda h: h.is_global_position_ok and h.is_home_position_ok and h.is_armable, 10, "health")
        emit({"event": "position", "fix": gps.fix_type.name, "satellites": gps.num_satellites,
              "home_amsl": home.absolute_altitude_m,
              **{f"health_{k.removeprefix('is_')}": v for k, v in vars(health).items()}})

        code = fly(system, telemetry, streams, float(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6]), home) \
            if scenario == "flight" else arm_once(system, texts)
        if code == 0:
            emit({"event": "done"})
        return code
    except TimeoutError as e:
        emit({"event": "error", "what": f"timed out waiting for {e}"})
        return 1
    finally:
        mavsdk.destroy()


if __name__ == "__main__":
    sys.exit(main())
