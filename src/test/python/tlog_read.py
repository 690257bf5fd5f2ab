"""Reads a tlog with pymavlink's mavutil, as MAVProxy's log tools do.

Usage: tlog_read.py PATH
Prints one JSON object per message ("item": message id, sequence, source system and component,
type, timestamp in microseconds from msg._timestamp; for GLOBAL_POSITION_INT also lat and lon in
degrees × 10⁷ and alt in mm), then "end" with the count. Bounded: at
most 1,000,000 messages.
"""
import json
import os
import sys

os.environ["MAVLINK20"] = "1"
from pymavlink import mavutil  # noqa: E402


def main() -> None:
    log = mavutil.mavlink_connection(sys.argv[1])
    count = 0
    while count < 1_000_000:
        msg = log.recv_msg()
        if msg is None:
            break
        count += 1
        item = {
            "event": "item",
            "type": msg.get_type(),
            "id": msg.get_msgId(),
            "seq": msg.get_seq(),
            "sys": msg.get_srcSystem(),
            "comp": msg.get_srcComponent(),
            "t_us": int(round(msg._timestamp * 1e6)),
        }
        if msg.get_type() == "GLOBAL_POSITION_INT":
            item.update(lat=msg.lat, lon=msg.lon, alt=msg.alt)
        print(json.dumps(item), flush=True)
    print(json.dumps({"event": "end", "count": count}), flush=True)


if __name__ == "__main__":
    main()
