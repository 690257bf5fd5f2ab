"""A vehicle that is not Pod's answering commands: pymavlink replies to COMMAND_LONG / COMMAND_INT
with scripted COMMAND_ACK sequences.

Usage: pymavlink_command_vehicle.py PORT SYSID SECONDS

Sends a PX4 quadrotor heartbeat at 1 Hz to 127.0.0.1:PORT and answers, per MAV_CMD:
    241 PREFLIGHT_CALIBRATION  IN_PROGRESS 10 %, IN_PROGRESS 60 % (0.15 s apart), then ACCEPTED
                               with result_param2 7
    400 COMPONENT_ARM_DISARM   TEMPORARILY_REJECTED to the first two sends, ACCEPTED after
    178 DO_CHANGE_SPEED        ACCEPTED addressed to system 99 (not the asker), ACCEPTED from
                               component 154 (not the autopilot), STATUSTEXTs at NOTICE and at WARNING,
                               then DENIED with result_param2 3
    20 NAV_RETURN_TO_LAUNCH    ACCEPTED as a MAVLink 1.0 frame from the v1.0 dialect: command and
                               result only (3 bytes)
    17 NAV_LOITER_UNLIM        ACCEPTED as pymavlink's force_mavlink1 sends it: a MAVLink 1 frame
                               that still carries the extension fields (10 bytes)
    21 NAV_LAND                ACCEPTED with every field after the command zero, target 0/0: MAVLink 2
                               drops the trailing zeros, down to one payload byte (21's low byte)
    anything else              ACCEPTED
Prints one JSON object per line on stdout:
    {"event": "ready"}
    {"event": "command", "command": .., "kind": "long"|"int", "confirmation": .., "x": .., "y": .., "z": ..,
     "param1": .., "frame": ..}
    {"event": "ack", "command": .., "result": .., "progress": .., "result_param2": .., "target_system": ..,
     "from_component": .., "mavlink": "1.0"|1|2, "magic": 254|253, "payload_len": ..}
Exits after SECONDS. Loopback only; the loop is bounded.
"""
import json
import os
import sys
import time

os.environ["MAVLINK20"] = "1"
from pymavlink import mavutil  # noqa: E402
from pymavlink.dialects.v10 import common as mav10  # noqa: E402
from pymavlink.dialects.v20 import common as mav  # noqa: E402


def emit(obj: dict) -> None:
    sys.stdout.write(json.dumps(obj) + "\n")
    sys.stdout.flush()


def main() -> None:
    port, sysid, seconds = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
    link = mavutil.mavlink_connection(f"udpout:127.0.0.1:{port}", source_system=sysid, source_component=1)
    # MAVLink 1.0's COMMAND_ACK has no extension fields; this encoder writes through the same socket.
    link_v10 = mav10.MAVLink(link, srcSystem=sysid, srcComponent=1)
    start = time.monotonic()
    next_heartbeat = start
    pending = []  # (due, ack fields) sent once due
    sends = {}  # MAV_CMD -> how many times it was received
    emit({"event": "ready"})

    def ack(command, result, to, progress=0, result_param2=0, from_component=1, mavlink=2, after=0.0):
        pending.append((time.monotonic() + after, dict(command=command, result=result, progress=progress,
                                                       result_param2=result_param2, target_system=to[0],
                                                       target_component=to[1], from_component=from_component,
                                                       mavlink=mavlink)))

    def send_due(now):
        for item in [p for p in pending if p[0] <= now]:
            pending.remove(item)
            a = item[1]
            if a["mavlink"] == "1.0":
                msg = mav10.MAVLink_command_ack_message(a["command"], a["result"])
                link_v10.send(msg)
            else:
                msg = mav.MAVLink_command_ack_message(a["command"], a["result"], a["progress"], a["result_param2"],
                                                      a["target_system"], a["target_component"])
                link.mav.srcComponent = a["from_component"]
                link.mav.send(msg, force_mavlink1=a["mavlink"] == 1)
                link.mav.srcComponent = 1
            buf = msg.get_msgbuf()
            emit({"event": "ack", "command": a["command"], "result": a["result"], "progress": a["progress"],
                  "result_param2": a["result_param2"], "target_system": a["target_system"],
                  "from_component": a["from_component"], "mavlink": a["mavlink"], "magic": buf[0],
                  "payload_len": buf[1]})

    loops = 0
    while time.monotonic() - start < seconds and loops < 100_000:
        loops += 1
        now = time.monotonic()
        if now >= next_heartbeat:
            link.mav.heartbeat_send(mav.MAV_TYPE_QUADROTOR, mav.MAV_AUTOPILOT_PX4, mav.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED,
                                    0, mav.MAV_STATE_STANDBY)
            next_heartbeat = now + 1.0
        send_due(now)
        msg = link.recv_match(type=["COMMAND_LONG", "COMMAND_INT"], blocking=True, timeout=0.02)
        if msg is None or msg.target_system != sysid:
            continue
        kind = "long" if msg.get_type() == "COMMAND_LONG" else "int"
        emit({"event": "command", "command": msg.command, "kind": kind,
              "confirmation": getattr(msg, "confirmation", 0), "param1": msg.param1,
              "x": msg.param5 if kind == "long" else msg.x, "y": msg.param6 if kind == "long" else msg.y,
              "z": msg.param7 if kind == "long" else msg.z, "frame": getattr(msg, "frame", -1)})
        asker = (msg.get_srcSystem(), msg.get_srcComponent())
        sends[msg.command] = sends.get(msg.command, 0) + 1
        if msg.command == 241:
            ack(241, mav.MAV_RESULT_IN_PROGRESS, asker, progress=10)
            ack(241, mav.MAV_RESULT_IN_PROGRESS, asker, progress=60, after=0.15)
            ack(241, mav.MAV_RESULT_ACCEPTED, asker, result_param2=7, after=0.3)
        elif msg.command == 400:
            result = mav.MAV_RESULT_TEMPORARILY_REJECTED if sends[400] <= 2 else mav.MAV_RESULT_ACCEPTED
            ack(400, result, asker)
        elif msg.command == 178:
            ack(178, mav.MAV_RESULT_ACCEPTED, (99, 190))
            ack(178, mav.MAV_RESULT_ACCEPTED, asker, from_component=154)
            link.mav.statustext_send(mav.MAV_SEVERITY_NOTICE, b"Speed change requested")
            link.mav.statustext_send(mav.MAV_SEVERITY_WARNING, b"Speed 12 m/s above limit")
            emit({"event": "status_text", "texts": 2})
            ack(178, mav.MAV_RESULT_DENIED, asker, result_param2=3, after=0.05)
        elif msg.command == 20:
            ack(20, mav.MAV_RESULT_ACCEPTED, asker, mavlink="1.0")
        elif msg.command == 17:
            ack(17, mav.MAV_RESULT_ACCEPTED, asker, mavlink=1)
        elif msg.command == 21:
            ack(21, mav.MAV_RESULT_ACCEPTED, (0, 0))
        else:
            ack(msg.command, mav.MAV_RESULT_ACCEPTED, asker)
        send_due(time.monotonic())


if __name__ == "__main__":
    main()
