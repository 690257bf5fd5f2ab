"""MAVSDK 4 as the ground station: uploads a mission with MissionRaw into whichever vehicle it hears.

Usage: mavsdk_gcs.py LISTEN_PORT ITEMS_JSON SECONDS [--download]

Listens with udpin://127.0.0.1:LISTEN_PORT, waits for the first autopilot to send a heartbeat
there, uploads ITEMS_JSON (a JSON array of objects with the MISSION_ITEM_INT fields seq, frame,
command, current, autocontinue, param1..param4, x, y, z, mission_type) with
MissionRaw.upload_mission, and with --download downloads the mission back with
MissionRaw.download_mission. Prints one JSON object per line on stdout:
    {"event": "ready", "version": ..}
    {"event": "system", "sysid": .., "autopilot": "ARDUPILOT"}
    {"event": "uploaded", "result": "SUCCESS", "seconds": ..}
    {"event": "item", ...fields...}                  with --download, one per downloaded item
    {"event": "downloaded", "result": "SUCCESS", "count": N, "seconds": ..}
    {"event": "done"}
A failed step prints its MissionRaw result instead of SUCCESS and the script exits 1. The whole
run is bounded by SECONDS (exit 3 when they pass). Loopback only.
"""
import json
import os
import sys
import threading
import time

from mavsdk_peer_io import FIELDS, download, emit, upload
from mavsdk import ComponentType, Configuration, ConnectionResult, Mavsdk
from mavsdk.plugins.mission_raw import MissionItem, MissionRaw


def watchdog(seconds: float) -> None:
    time.sleep(seconds)
    emit({"event": "error", "what": f"gave up after {seconds} s"})
    os._exit(3)


def main() -> int:
    port, items_json, seconds = int(sys.argv[1]), sys.argv[2], float(sys.argv[3])
    download_too = "--download" in sys.argv[4:]
    threading.Thread(target=watchdog, args=(seconds,), daemon=True).start()
    items = [MissionItem(**{f: item[f] for f in FIELDS}) for item in json.loads(items_json)]

    mavsdk = Mavsdk(Configuration.create_with_component_type(ComponentType.GROUND_STATION))
    try:
        result = mavsdk.add_any_connection(f"udpin://127.0.0.1:{port}")
        if result != ConnectionResult.SUCCESS:
            emit({"event": "error", "what": f"add_any_connection: {ConnectionResult(result).name}"})
            return 2
        emit({"event": "ready", "version": mavsdk.version()})
        system = mavsdk.first_autopilot(timeout_s=seconds)
        if system is None:
            emit({"event": "error", "what": "no autopilot heard"})
            return 2
        emit({"event": "system", "sysid": system.get_system_id(), "autopilot": system.autopilot_type().name})
        mission = MissionRaw(system)

        if not upload(mission, items, time.monotonic()):
            return 1
        if download_too and not download(mission, time.monotonic()):
            return 1
        emit({"event": "done"})
        return 0
    finally:
        mavsdk.destroy()


if __name__ == "__main__":
    sys.exit(main())
