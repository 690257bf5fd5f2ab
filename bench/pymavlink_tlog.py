#!/usr/bin/env python3
"""pymavlink reading a tlog: the job Pod's TlogTracks.read does, the way a pymavlink user does it.

mavutil.mavlink_connection(PATH) opens a *.tlog as a mavlogfile; recv_msg() is called until it
returns None at the end of the file. Every message is parsed (CRC_EXTRA checked, fastcrc when
installed, as pymavlink does by itself) and decoded; the GLOBAL_POSITION_INT of each system that
sent a vehicle HEARTBEAT are kept as its track (time, latitude and longitude in degrees, altitude
in metres), positions without a fix (0, 0) skipped, as Pod does.

Runs the read --warmup times (not kept) and --runs times, and prints one JSON line per read:
{"event": "run", "warmup": bool, "seconds", "cpu_seconds" (process CPU), "records", "bad" (BAD_DATA),
"positions": {sysid: count}, "last": {sysid: [lat, lon, alt] as sent, in 1e-7 degrees and mm}},
then {"event": "done"}. Each read is bounded by the file: nothing waits.
"""

import argparse
import json
import os
import sys
import time

# A tlog of MAVLink 2 frames: mavutil would switch to MAVLink 2 at the first frame by itself
# (auto_mavlink_version); asking for it up front keeps the first read like the others.
os.environ.setdefault("MAVLINK20", "1")

from pymavlink import mavutil  # noqa: E402  (after MAVLINK20 is set)

GCS_TYPES = {mavutil.mavlink.MAV_TYPE_GCS, mavutil.mavlink.MAV_TYPE_ONBOARD_CONTROLLER}


def read_tracks(path):
    """Every vehicle's track in the tlog at path, and the number of messages and of BAD_DATA read."""
    conn = mavutil.mavlink_connection(path)
    vehicles = set()
    tracks = {}
    last = {}
    records = 0
    bad = 0
    try:
        while True:
            msg = conn.recv_msg()
            if msg is None:
                break
            records += 1
            kind = msg.get_type()
            if kind == "BAD_DATA":
                bad += 1
            elif kind == "HEARTBEAT":
                if msg.type not in GCS_TYPES and msg.autopilot != mavutil.mavlink.MAV_AUTOPILOT_INVALID:
                    vehicles.add(msg.get_srcSystem())
            elif kind == "GLOBAL_POSITION_INT":
                system = msg.get_srcSystem()
                if system in vehicles and not (msg.lat == 0 and msg.lon == 0):
                    tracks.setdefault(system, []).append((msg._timestamp, msg.lat * 1e-7, msg.lon * 1e-7, msg.alt * 1e-3))
                    last[system] = (msg.lat, msg.lon, msg.alt)
    finally:
        conn.close()
    return tracks, last, records, bad


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("path")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--warmup", type=int, default=1)
    args = parser.parse_args()
    if not 0 <= args.warmup <= 100 or not 1 <= args.runs <= 100:
        sys.exit("--warmup must be in 0..100 and --runs in 1..100")
    for i in range(args.warmup + args.runs):
        cpu0 = time.process_time()
        t0 = time.perf_counter()
        tracks, last, records, bad = read_tracks(args.path)
        seconds = time.perf_counter() - t0
        cpu = time.process_time() - cpu0
        print(json.dumps({
            "event": "run",
            "warmup": i < args.warmup,
            "seconds": seconds,
            "cpu_seconds": cpu,
            "records": records,
            "bad": bad,
            "positions": {str(k): len(v) for k, v in sorted(tracks.items())},
            "last": {str(k): list(v) for k, v in sorted(last.items())},
        }), flush=True)
    print(json.dumps({"event": "done"}), flush=True)


if __name__ == "__main__":
    main()
