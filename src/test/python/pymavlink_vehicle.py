"""A vehicle that is not Pod's: pymavlink sends HEARTBEAT and GLOBAL_POSITION_INT to a UDP port.

Usage: pymavlink_vehicle.py PORT SYSID SECONDS
Sends a fixed-wing ArduPilot heartbeat (mode AUTO) at 1 Hz and a position at 5 Hz to
127.0.0.1:PORT for SECONDS seconds, then exits. Loopback only; the loop is bounded.
"""
import os
import sys
import time

os.environ["MAVLINK20"] = "1"
from pymavlink import mavutil  # noqa: E402
from pymavlink.dialects.v20 import ardupilotmega as mav  # noqa: E402

LAT, LON, ALT_MM, REL_MM = 411_234_567, -85_432_100, 95_500, 12_300


def main() -> None:
    port, sysid, seconds = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
    link = mavutil.mavlink_connection(f"udpout:127.0.0.1:{port}", source_system=sysid, source_component=1)
    start = time.monotonic()
    ticks = 0
    while time.monotonic() - start < seconds and ticks < 10_000:
        if ticks % 5 == 0:
            link.mav.heartbeat_send(mav.MAV_TYPE_FIXED_WING, mav.MAV_AUTOPILOT_ARDUPILOTMEGA,
                                    mav.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED | mav.MAV_MODE_FLAG_SAFETY_ARMED,
                                    10, mav.MAV_STATE_ACTIVE)
        link.mav.global_position_int_send(int((time.monotonic() - start) * 1000), LAT, LON, ALT_MM, REL_MM,
                                          150, -20, 0, 9000)
        ticks += 1
        time.sleep(0.2)


if __name__ == "__main__":
    main()
