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
import sys
import time

from mavsdk_peer_io import FIELDS, download, emit, listen, start_watchdog, upload
from mavsdk import ComponentType, Configuration, Mavsdk
from mavsdk.plugins.mission_raw import MissionItem, MissionRaw


def main() -> int:
    port, items_json, seconds = int(sys.argv[1]), sys.argv[2], float(sys.argv[3])
    download_too = "--download" in sys.argv[4:]
    start_watchdog(seconds)
    items = [MissionItem(**{f: item[f] for f in FIELDS}) for item in json.loads(items_json)]

    mavsdk = Mavsdk(Configuration.create_with_component_type(ComponentType.GROUND_STATION))
    try:
        if not listen(mavsdk, port):
            return 2
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
