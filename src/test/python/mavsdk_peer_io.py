"""Shared by the MAVSDK peers (tests and bench/mavsdk_mission.py): one JSON object per line on
stdout, thread-safe, listening as a ground station, a watchdog, and the timed MissionRaw steps of
a ground station."""
import json
import os
import sys
import threading
import time

from mavsdk import ConnectionResult
from mavsdk.plugins.mission_raw import MissionRawError

#: MissionItem fields in the order the peers print them (named as in MISSION_ITEM_INT).
FIELDS = ("seq", "frame", "command", "current", "autocontinue", "param1", "param2", "param3", "param4",
          "x", "y", "z", "mission_type")

_out = threading.Lock()


def emit(obj: dict) -> None:
    # Watchdog threads print too: one whole line at a time.
    with _out:
        sys.stdout.write(json.dumps(obj) + "\n")
        sys.stdout.flush()


def _seconds(start: float) -> float:
    return round(time.monotonic() - start, 3)


def upload(mission, items, start: float) -> bool:
    """MissionRaw.upload_mission, reported as an "uploaded" event timed from start."""
    try:
        mission.upload_mission(items)
    except MissionRawError as e:
        emit({"event": "uploaded", "result": e.result.name, "seconds": _seconds(start)})
        return False
    emit({"event": "uploaded", "result": "SUCCESS", "seconds": _seconds(start)})
    return True


def download(mission, start: float) -> bool:
    """MissionRaw.download_mission: an "item" event per item, then "downloaded" timed from start."""
    try:
        back = mission.download_mission()
    except MissionRawError as e:
        emit({"event": "downloaded", "result": e.result.name, "count": 0, "seconds": _seconds(start)})
        return False
    seconds = _seconds(start)
    for item in back:
        emit({"event": "item", **{name: getattr(item, name) for name in FIELDS}})
    emit({"event": "downloaded", "result": "SUCCESS", "count": len(back), "seconds": seconds})
    return True


def listen(mavsdk, port: int) -> bool:
    """Listens as a ground station on 127.0.0.1:port and says "ready"; False (and an "error" line)
    when MAVSDK cannot open the port."""
    result = mavsdk.add_any_connection(f"udpin://127.0.0.1:{port}")
    if result != ConnectionResult.SUCCESS:
        emit({"event": "error", "what": f"add_any_connection: {ConnectionResult(result).name}"})
        return False
    emit({"event": "ready", "version": mavsdk.version()})
    return True


def start_watchdog(seconds: float) -> None:
    """Ends the process (exit 3, with an "error" line) after `seconds`, whatever it is waiting on."""
    def watch() -> None:
        time.sleep(seconds)
        emit({"event": "error", "what": f"gave up after {seconds} s"})
        os._exit(3)
    threading.Thread(target=watch, daemon=True).start()
