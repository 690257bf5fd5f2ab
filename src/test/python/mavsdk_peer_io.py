"""Shared by the MAVSDK peers (tests and bench/mavsdk_mission.py): one JSON object per line on
stdout, thread-safe, and the timed MissionRaw steps of a ground station."""
import json
import sys
import threading
import time

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
