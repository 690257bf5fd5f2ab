"""Output shared by the MAVSDK test peers: one JSON object per line on stdout, thread-safe."""
import json
import sys
import threading

#: MissionItem fields in the order the peers print them.
FIELDS = ("seq", "frame", "command", "current", "autocontinue", "param1", "param2", "param3", "param4",
          "x", "y", "z", "mission_type")

_out = threading.Lock()


def emit(obj: dict) -> None:
    with _out:
        sys.stdout.write(json.dumps(obj) + "\n")
        sys.stdout.flush()
