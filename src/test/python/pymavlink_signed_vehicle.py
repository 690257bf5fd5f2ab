"""A vehicle that is not Pod's, with MAVLink 2 signing: pymavlink signs what it sends and checks
what it receives with the key given, and refuses every unsigned frame (an allow_unsigned_callback
that allows nothing).

Usage: pymavlink_signed_vehicle.py PORT SYSID KEY_HEX SECONDS

Sends an ArduCopter quadrotor heartbeat at 1 Hz to 127.0.0.1:PORT, signed on link id 2; answers
COMMAND_LONG COMPONENT_ARM_DISARM (400) with COMMAND_ACK ACCEPTED and arms or disarms as asked
(the heartbeat's base_mode says so), and any other command with ACCEPTED.
Prints one JSON object per line on stdout:
    {"event": "ready"}
    {"event": "command", "command": .., "signed": true|false}   (only frames pymavlink accepted)
    {"event": "stats", "goodsig": .., "badsig": .., "reject": .., "unsigned": ..}   every 0.5 s
Exits after SECONDS. Loopback only; the loop is bounded.
"""
import json
import os
import sys
import time

os.environ["MAVLINK20"] = "1"
from pymavlink import mavutil  # noqa: E402

ARMED = 128  # MAV_MODE_FLAG_SAFETY_ARMED


def emit(obj: dict) -> None:
    sys.stdout.write(json.dumps(obj) + "\n")
    sys.stdout.flush()


def main() -> None:
    port, sysid, key, seconds = int(sys.argv[1]), int(sys.argv[2]), bytes.fromhex(sys.argv[3]), float(sys.argv[4])
    link = mavutil.mavlink_connection(f"udpout:127.0.0.1:{port}", source_system=sysid, source_component=1)
    # A callback that allows nothing: unsigned frames are refused and counted in reject_count.
    link.setup_signing(key, sign_outgoing=True, allow_unsigned_callback=lambda mav, msg_id: False, link_id=2)
    signing = link.mav.signing
    start = time.monotonic()
    next_heartbeat = start
    next_stats = start
    armed = False
    emit({"event": "ready"})
    while time.monotonic() - start < seconds:
        now = time.monotonic()
        if now >= next_heartbeat:
            link.mav.heartbeat_send(mavutil.mavlink.MAV_TYPE_QUADROTOR, mavutil.mavlink.MAV_AUTOPILOT_ARDUPILOTMEGA,
                                    ARMED if armed else 0, 4, mavutil.mavlink.MAV_STATE_STANDBY)
            next_heartbeat = now + 1.0
        if now >= next_stats:
            emit({"event": "stats", "goodsig": signing.goodsig_count, "badsig": signing.badsig_count,
                  "reject": signing.reject_count, "unsigned": signing.unsigned_count})
            next_stats = now + 0.5
        try:
            m = link.recv_match(type="COMMAND_LONG", blocking=True, timeout=0.05)
        except Exception:  # pymavlink raises for a frame its signing refuses; it is counted above
            m = None
        if m is None or m.target_system not in (0, sysid):
            continue
        emit({"event": "command", "command": m.command, "signed": bool(getattr(m, "_signed", False))})
        if m.command == mavutil.mavlink.MAV_CMD_COMPONENT_ARM_DISARM:
            armed = m.param1 == 1
        link.mav.command_ack_send(m.command, mavutil.mavlink.MAV_RESULT_ACCEPTED, 0, 0, m.get_srcSystem(), m.get_srcComponent())


if __name__ == "__main__":
    main()
