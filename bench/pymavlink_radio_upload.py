"""Uploads a QGC WPL mission with pymavlink's mavutil, answering each MISSION_REQUEST(_INT) with
MISSION_ITEM_INT until MISSION_ACK, and prints one JSON line per step for the radio benchmark
(pod.bench.radio.RadioUploadBenchKt): {"event":"ready"} once the vehicle's HEARTBEAT is heard,
then {"event":"uploaded","seconds":...} (MISSION_COUNT sent to MISSION_ACK ACCEPTED) or
{"event":"error","message":...}. Bounded by --timeout."""
import argparse
import json
import sys
import time

from pymavlink import mavutil, mavwp


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--connect", required=True)
    p.add_argument("--wpl", required=True)
    p.add_argument("--timeout", type=float, default=120)
    a = p.parse_args()
    m = mavutil.mavlink_connection(a.connect, source_system=255, source_component=190)
    if m.wait_heartbeat(timeout=30) is None:
        print(json.dumps({"event": "error", "message": "no heartbeat"}), flush=True)
        return 2
    loader = mavwp.MAVWPLoader()
    loader.load(a.wpl)
    n = loader.count()
    print(json.dumps({"event": "ready", "items": n}), flush=True)
    t0 = time.monotonic()
    m.mav.mission_count_send(m.target_system, m.target_component, n)
    while time.monotonic() - t0 < a.timeout:
        msg = m.recv_match(type=["MISSION_REQUEST", "MISSION_REQUEST_INT", "MISSION_ACK"], blocking=True, timeout=1)
        if msg is None or msg.get_srcSystem() != m.target_system:
            continue
        if msg.get_type() == "MISSION_ACK":
            if msg.type == 0:
                print(json.dumps({"event": "uploaded", "seconds": time.monotonic() - t0}), flush=True)
                return 0
            print(json.dumps({"event": "error", "message": "MISSION_ACK %d" % msg.type}), flush=True)
            return 1
        wp = loader.wp(msg.seq)
        m.mav.mission_item_int_send(
            m.target_system, m.target_component, wp.seq, wp.frame, wp.command, 1 if wp.seq == 0 else 0,
            wp.autocontinue, wp.param1, wp.param2, wp.param3, wp.param4,
            int(round(wp.x * 1e7)), int(round(wp.y * 1e7)), wp.z, 0)
    print(json.dumps({"event": "error", "message": "timeout"}), flush=True)
    return 1


if __name__ == "__main__":
    sys.exit(main())
