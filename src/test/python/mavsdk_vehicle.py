"""MAVSDK 4 as the vehicle: an AUTOPILOT component with MissionRawServer, sending to a ground station.

Usage: mavsdk_vehicle.py GCS_PORT SYSID SECONDS [--no-mission-server] [--param=NAME=VALUE ...]
                         [--action=armable|refusing]

Connects with udpout://127.0.0.1:GCS_PORT (MAVSDK 4 sends its heartbeat there at 1 Hz and answers
whoever talks back), so a ground station listening on that port finds it. Every list a ground
station uploads is printed on stdout, one JSON object per line:
    {"event": "item", "upload": K, "seq": .., "frame": .., "command": .., "current": ..,
     "autocontinue": .., "param1": .., "param2": .., "param3": .., "param4": .., "x": .., "y": ..,
     "z": .., "mission_type": ..}        one per item, in order
    {"event": "upload", "upload": K, "result": "SUCCESS", "count": N}   after the items
    {"event": "clear", "mission_type": T}      a MISSION_CLEAR_ALL the server acted on
    {"event": "current", "seq": S}             the server's current item changed
Floats are printed with repr() (NaN as NaN), which reads back as the same float32 value.
With --no-mission-server the plugin is not created: the vehicle then ignores the mission protocol.

Each --param=NAME=VALUE is provided through ParamServer before the link is up, as an int when
VALUE has no "." and as a float otherwise; a ground station's change is printed as
    {"event": "param_changed", "name": .., "kind": "int"|"float", "value": ..}
--action creates ActionServer: "armable" arms on request and allows takeoff, "refusing" does
neither. What it hears is printed as
    {"event": "arm_disarm", "result": "SUCCESS"|"COMMAND_DENIED", "arm": true, "force": false}
    {"event": "takeoff", "result": "SUCCESS"|"COMMAND_DENIED", "allowed": true}
Exits after SECONDS, or when stdin closes. Loopback only; every loop is bounded.
"""
import sys
import threading
import time

from mavsdk_peer_io import FIELDS, emit
from mavsdk import ComponentType, Configuration, ConnectionResult, Mavsdk
from mavsdk.plugins.action_server import ActionServer
from mavsdk.plugins.mission_raw_server import MissionRawServer
from mavsdk.plugins.param_server import ParamServer


def provide_params(mavsdk: Mavsdk, params) -> ParamServer:
    server = ParamServer(mavsdk.server_component())
    for name, value in params:
        if "." in value:
            server.provide_param_float(name, float(value))
        else:
            server.provide_param_int(name, int(value))
    server.subscribe_changed_param_int(
        lambda p, _: emit({"event": "param_changed", "name": p.name, "kind": "int", "value": p.value}))
    server.subscribe_changed_param_float(
        lambda p, _: emit({"event": "param_changed", "name": p.name, "kind": "float", "value": p.value}))
    return server


def serve_actions(mavsdk: Mavsdk, mode: str) -> ActionServer:
    if mode not in ("armable", "refusing"):
        raise SystemExit(f"--action must be armable or refusing, was {mode}")
    server = ActionServer(mavsdk.server_component())
    allowed = mode == "armable"
    server.set_armable(allowed, allowed)
    server.set_allow_takeoff(allowed)
    server.subscribe_arm_disarm(lambda result, request, _: emit(
        {"event": "arm_disarm", "result": result.name, "arm": request.arm, "force": request.force}))
    server.subscribe_takeoff(lambda result, allowed_now, _: emit(
        {"event": "takeoff", "result": result.name, "allowed": bool(allowed_now)}))
    return server


def main() -> None:
    port, sysid, seconds = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
    flags = sys.argv[4:]
    with_server = "--no-mission-server" not in flags
    params = [flag.removeprefix("--param=").split("=", 1) for flag in flags if flag.startswith("--param=")]
    action_mode = next((flag.removeprefix("--action=") for flag in flags if flag.startswith("--action=")), None)
    config = Configuration.create_with_component_type(ComponentType.AUTOPILOT)
    config.system_id = sysid
    mavsdk = Mavsdk(config)
    try:
        # Parameters are provided before the link is up: a ground station may ask for them at once.
        param_server = provide_params(mavsdk, params) if params else None
        action_server = serve_actions(mavsdk, action_mode) if action_mode else None
        result = mavsdk.add_any_connection(f"udpout://127.0.0.1:{port}")
        if result != ConnectionResult.SUCCESS:
            emit({"event": "error", "what": f"add_any_connection: {ConnectionResult(result).name}"})
            sys.exit(2)
        uploads = [0]
        server = None
        if with_server:
            server = MissionRawServer(mavsdk.server_component())

            def on_incoming(result, plan, _user_data):
                uploads[0] += 1
                k = uploads[0]
                for item in plan.mission_items:
                    emit({"event": "item", "upload": k, **{f: getattr(item, f) for f in FIELDS}})
                emit({"event": "upload", "upload": k, "result": result.name, "count": len(plan.mission_items)})

            server.subscribe_incoming_mission(on_incoming)
            server.subscribe_clear_all(lambda mission_type, _: emit({"event": "clear", "mission_type": mission_type}))
            server.subscribe_current_item_changed(lambda item, _: emit({"event": "current", "seq": item.seq}))
        emit({"event": "ready", "version": mavsdk.version(), "sysid": sysid, "mission_server": with_server,
              "params": len(params), "action": action_mode or "none"})
        stdin_closed = threading.Event()

        def watch_stdin():
            sys.stdin.read()
            stdin_closed.set()

        threading.Thread(target=watch_stdin, daemon=True).start()
        stdin_closed.wait(timeout=seconds)
    finally:
        mavsdk.destroy()


if __name__ == "__main__":
    main()
