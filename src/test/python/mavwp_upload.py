"""pymavlink as a ground station that speaks the legacy mission messages, as MAVProxy's wp module
and scripts built on mavwp do: uploads answer MISSION_REQUEST(_INT) with MISSION_ITEM (float
latitude/longitude), downloads ask with MISSION_REQUEST and expect MISSION_ITEM back.

Usage: mavwp_upload.py PORT SYSID WPL_FILE

Listens on udpin:127.0.0.1:PORT for the vehicle SYSID, uploads the mission in WPL_FILE (QGC WPL 110,
loaded with mavwp), then downloads it back with MISSION_REQUEST. Prints one JSON object per line:
    {"event": "uploaded", "result": R}                 the vehicle's final MISSION_ACK type
    {"event": "item", "seq": .., "msg": "MISSION_ITEM", "frame": .., "command": .., "x": .., "y": .., "z": ..}
    {"event": "downloaded", "count": N}
Every wait is bounded (10 s); on a timeout it prints {"event": "error", "what": ...} and exits 1.
"""
import json
import os
import sys
import time

os.environ["MAVLINK20"] = "1"

from pymavlink import mavutil, mavwp  # noqa: E402


def emit(obj):
    print(json.dumps(obj), flush=True)


def fail(what):
    emit({"event": "error", "what": what})
    sys.exit(1)


def main():
    port, sysid, path = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    link = mavutil.mavlink_connection(f"udpin:127.0.0.1:{port}", source_system=255, source_component=190)
    if link.wait_heartbeat(timeout=10) is None:
        fail("no heartbeat")
    while link.target_system != sysid:
        if link.wait_heartbeat(timeout=10) is None:
            fail("no heartbeat from the vehicle")
    loader = mavwp.MAVWPLoader(target_system=sysid, target_component=1)
    loader.load(path)
    link.waypoint_count_send(loader.count())
    deadline = time.time() + 10
    while True:
        m = link.recv_match(type=["MISSION_REQUEST", "MISSION_REQUEST_INT", "MISSION_ACK"], blocking=True, timeout=1)
        if time.time() > deadline:
            fail("upload timed out")
        if m is None:
            continue
        if m.get_type() == "MISSION_ACK":
            emit({"event": "uploaded", "result": m.type})
            break
        link.mav.send(loader.wp(m.seq))  # a MISSION_ITEM, as mavwp holds items
    link.waypoint_request_list_send()
    m = link.recv_match(type="MISSION_COUNT", blocking=True, timeout=10)
    if m is None:
        fail("no MISSION_COUNT")
    count = m.count
    for seq in range(count):
        link.waypoint_request_send(seq)  # the legacy MISSION_REQUEST
        m = link.recv_match(type=["MISSION_ITEM", "MISSION_ITEM_INT"], blocking=True, timeout=10)
        if m is None:
            fail(f"no answer for item {seq}")
        emit({"event": "item", "seq": m.seq, "msg": m.get_type(), "frame": m.frame, "command": m.command,
              "x": m.x, "y": m.y, "z": m.z})
    link.mav.mission_ack_send(sysid, 1, 0)
    emit({"event": "downloaded", "count": count})


if __name__ == "__main__":
    main()
