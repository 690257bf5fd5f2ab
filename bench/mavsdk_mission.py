#!/usr/bin/env python3
"""MAVSDK 4 as the ground station of the mission-transfer benchmark (pod.bench.mission).

Usage: mavsdk_mission.py --port P --items FILE [--download] [--discover-seconds S] [--transfer-seconds T]

Listens with udpin://127.0.0.1:P, waits for the first autopilot, uploads the items in FILE (a
JSON array of MISSION_ITEM_INT fields, as src/test/python/mavsdk_gcs.py takes them) with
MissionRaw.upload_mission and, with --download, downloads them back. The items come from a file,
not argv: a 1000-item mission is larger than Linux lets one argument be (128 KiB).

Prints one JSON object per line on stdout:
    {"event": "ready", "version": ..}
    {"event": "system", "sysid": .., "autopilot": "PX4", "seconds": ..}
    {"event": "uploaded", "result": "SUCCESS" | MissionRaw result name | "WATCHDOG", "seconds": ..}
    {"event": "item", ...fields...}                 one per downloaded item
    {"event": "downloaded", "result": ..., "count": N, "seconds": ..}
    {"event": "done"}
Never hangs: each step has its own deadline (discovery S seconds, each transfer T seconds); a
watchdog reports the step that overran with result "WATCHDOG" and exits 3. Loopback only.
"""
import argparse
import json
import os
import sys
import threading
import time

from mavsdk import ComponentType, Configuration, Mavsdk
from mavsdk.plugins.mission_raw import MissionItem, MissionRaw

# The output format and the timed MissionRaw steps are the interop tests' own.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src", "test", "python"))
from mavsdk_peer_io import FIELDS, download, emit, listen, upload  # noqa: E402


class Watchdog:
    """One deadline at a time: the step now running, its event name and when it started."""

    def __init__(self):
        self._lock = threading.Lock()
        self._step = None
        threading.Thread(target=self._watch, daemon=True).start()

    def arm(self, event: str, seconds: float) -> float:
        start = time.monotonic()
        with self._lock:
            self._step = (event, start, start + seconds)
        return start

    def _watch(self) -> None:
        while True:
            time.sleep(0.05)
            with self._lock:
                step = self._step
            if step is not None and time.monotonic() > step[2]:
                event, start, _ = step
                emit({"event": event, "result": "WATCHDOG", "count": 0,
                      "seconds": round(time.monotonic() - start, 3)})
                # mavsdk_server is a child process: os._exit skips destroy(), the harness kills the tree.
                os._exit(3)


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--port", type=int, required=True)
    parser.add_argument("--items", required=True)
    parser.add_argument("--download", action="store_true")
    parser.add_argument("--discover-seconds", type=float, default=30)
    parser.add_argument("--transfer-seconds", type=float, default=120)
    args = parser.parse_args()
    with open(args.items) as f:
        items = [MissionItem(**{name: item[name] for name in FIELDS}) for item in json.load(f)]

    watchdog = Watchdog()
    watchdog.arm("ready", args.discover_seconds)
    mavsdk = Mavsdk(Configuration.create_with_component_type(ComponentType.GROUND_STATION))
    try:
        if not listen(mavsdk, args.port):
            return 2

        start = watchdog.arm("system", args.discover_seconds)
        system = mavsdk.first_autopilot(timeout_s=args.discover_seconds)
        if system is None:
            emit({"event": "system", "result": "NO_AUTOPILOT", "seconds": round(time.monotonic() - start, 3)})
            return 2
        emit({"event": "system", "sysid": system.get_system_id(), "autopilot": system.autopilot_type().name,
              "seconds": round(time.monotonic() - start, 3)})
        mission = MissionRaw(system)

        if not upload(mission, items, watchdog.arm("uploaded", args.transfer_seconds)):
            return 1
        if args.download and not download(mission, watchdog.arm("downloaded", args.transfer_seconds)):
            return 1
        watchdog.arm("done", 10)
        emit({"event": "done"})
        return 0
    finally:
        mavsdk.destroy()


if __name__ == "__main__":
    sys.exit(main())
