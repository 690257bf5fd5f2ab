#!/usr/bin/env python3
"""Writes pymavlink test vectors for Pod's MAVLink codec.

Encodes a fixed set of messages (explicit field values, no randomness, no clock) with pymavlink's
ardupilotmega dialect as MAVLink 2 and as MAVLink 1, and writes one line per frame to
mavlink/src/test/resources/vectors/pymavlink-vectors.tsv:

    version  sysid  compid  seq  MESSAGE_NAME  {"field": value, ...}  hex-of-wire-bytes

The JSON holds every field of the message as pymavlink defines it (unset fields are 0, "" or
zeros), floats as the exact value of their float32, char arrays as strings, other arrays as lists.
A few MAVLink 2 frames are signed (fixed key, link id and timestamp); their JSON is the unsigned
message and the hex carries the 13-byte signature block.

It also writes pymavlink-messages.tsv: id, name, CRC_EXTRA and payload length without and with
extension fields of every ardupilotmega message, so the Kotlin test
can check the payload layout of every message class io.dronefleet knows.

Usage: python3 tools/gen_mavlink_vectors.py   (needs `pip install pymavlink`; run from anywhere)
"""
import json
import os
import struct
import sys

# pymavlink's mavutil picks the wire version from this variable; the dialect modules imported
# below are explicit about their version, but set it anyway so nothing in pymavlink disagrees.
os.environ["MAVLINK20"] = "1"

from pymavlink.dialects.v10 import ardupilotmega as v1  # noqa: E402
from pymavlink.dialects.v20 import ardupilotmega as v2  # noqa: E402
from pymavlink.generator import mavparse  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
OUT_DIR = os.path.join(HERE, "..", "mavlink", "src", "test", "resources", "vectors")

UINT64_MAX = 2**64 - 1
INT32_MIN = -(2**31)

# (MESSAGE_NAME, {field: value}); fields left out are zero. Several value sets per message:
# typical, extremes (max unsigned, negative, min signed) and sets whose trailing fields are zero,
# so MAVLink 2 truncation is exercised. Extension fields are set in some sets (MAVLink 1 drops them).
MESSAGES = [
    ("HEARTBEAT", dict(type=2, autopilot=3, base_mode=81, custom_mode=4, system_status=4, mavlink_version=3)),
    ("HEARTBEAT", dict(type=6, autopilot=8, base_mode=0, custom_mode=0, system_status=0, mavlink_version=0)),
    ("HEARTBEAT", dict(type=1, autopilot=12, base_mode=217, custom_mode=0xFFFFFFFF, system_status=8, mavlink_version=3)),
    ("SYS_STATUS", dict(onboard_control_sensors_present=0x3FFFFFFF, onboard_control_sensors_enabled=0x0123ABCD,
                        onboard_control_sensors_health=0xFFFFFFFF, load=500, voltage_battery=12600, current_battery=-1,
                        battery_remaining=-1, drop_rate_comm=0, errors_comm=3, errors_count1=1, errors_count2=2,
                        errors_count3=3, errors_count4=65535)),
    ("SYS_STATUS", dict(onboard_control_sensors_present=1, load=1, voltage_battery=11000, current_battery=1520,
                        battery_remaining=87, onboard_control_sensors_present_extended=1,
                        onboard_control_sensors_enabled_extended=1, onboard_control_sensors_health_extended=1)),
    ("GLOBAL_POSITION_INT", dict(time_boot_ms=123456, lat=473977418, lon=85455939, alt=488000, relative_alt=15000,
                                 vx=120, vy=-340, vz=-5, hdg=27000)),
    ("GLOBAL_POSITION_INT", dict(time_boot_ms=0xFFFFFFFF, lat=-337974000, lon=-1511234567, alt=INT32_MIN,
                                 relative_alt=-1, vx=-32768, vy=32767, vz=0, hdg=65535)),
    ("GLOBAL_POSITION_INT", dict(time_boot_ms=1000, lat=1, lon=2, alt=3, relative_alt=4)),
    ("ATTITUDE", dict(time_boot_ms=5000, roll=0.1, pitch=-0.25, yaw=3.1415927, rollspeed=-0.001, pitchspeed=1e-7,
                      yawspeed=-2.5)),
    ("ATTITUDE", dict(time_boot_ms=1, roll=-0.0, pitch=3.4028235e38, yaw=-3.4028235e38, rollspeed=1.17549435e-38,
                      pitchspeed=0.0, yawspeed=0.0)),
    ("MISSION_CURRENT", dict(seq=3)),
    ("MISSION_CURRENT", dict(seq=65535, total=12, mission_state=3, mission_mode=1)),
    ("MISSION_CURRENT", dict(seq=0)),
    ("HOME_POSITION", dict(latitude=473977418, longitude=85455939, altitude=488000, x=0.5, y=-1.25, z=2.0,
                           q=[1.0, 0.0, 0.0, 0.0], approach_x=0.0, approach_y=0.0, approach_z=0.0)),
    ("HOME_POSITION", dict(latitude=-1, longitude=-2, altitude=-3, q=[0.5, -0.5, 0.5, -0.5], approach_z=-10.0,
                           time_usec=1700000000123456)),
    ("COMMAND_LONG", dict(target_system=1, target_component=1, command=400, confirmation=0, param1=1.0, param2=21196.0)),
    ("COMMAND_LONG", dict(target_system=1, target_component=0, command=176, confirmation=0, param1=1.0, param2=4.0,
                          param3=0, param4=0, param5=0, param6=0, param7=0)),
    ("COMMAND_LONG", dict(target_system=255, target_component=190, command=65535, confirmation=255, param1=-1.5,
                          param2=2.5, param3=-3.5, param4=4.5, param5=-5.5, param6=6.5, param7=-7.5)),
    ("COMMAND_ACK", dict(command=400, result=0)),
    ("COMMAND_ACK", dict(command=22, result=4, progress=50, result_param2=-12345, target_system=255,
                         target_component=190)),
    ("STATUSTEXT", dict(severity=6, text=b"PreArm: Need 3D Fix")),
    ("STATUSTEXT", dict(severity=0, text=b"x" * 50)),  # fills the field: no NUL on the wire
    ("STATUSTEXT", dict(severity=2, text="Höhe über Grund".encode("utf-8"), id=7, chunk_seq=1)),
    ("MISSION_ITEM_INT", dict(target_system=1, target_component=1, seq=0, frame=3, command=16, current=1,
                              autocontinue=1, param1=0.0, param2=2.0, param3=0.0, param4=float("0.0"),
                              x=473977418, y=85455939, z=30.0, mission_type=0)),
    ("MISSION_ITEM_INT", dict(target_system=1, target_component=1, seq=65535, frame=6, command=22, current=0,
                              autocontinue=0, param1=15.0, param4=-90.0, x=-337974000, y=-1511234567, z=-12.5,
                              mission_type=2)),
    ("MISSION_COUNT", dict(target_system=1, target_component=1, count=42)),
    ("MISSION_COUNT", dict(target_system=1, target_component=1, count=7, mission_type=1)),
    ("MISSION_REQUEST_INT", dict(target_system=255, target_component=190, seq=12)),
    ("MISSION_REQUEST_INT", dict(target_system=255, target_component=190, seq=0, mission_type=2)),
    ("MISSION_ACK", dict(target_system=255, target_component=190, type=0)),
    ("MISSION_ACK", dict(target_system=255, target_component=190, type=13, mission_type=1)),
    ("PARAM_VALUE", dict(param_id=b"SYSID_THISMAV", param_value=1.0, param_type=2, param_count=1234, param_index=17)),
    ("PARAM_VALUE", dict(param_id=b"WPNAV_SPEED_UP16", param_value=-250.5, param_type=9, param_count=65535,
                         param_index=65535)),  # 16 chars: no terminating NUL
    ("GPS_RAW_INT", dict(time_usec=1700000000123456, fix_type=3, lat=473977418, lon=85455939, alt=488000, eph=121,
                         epv=200, vel=35, cog=18000, satellites_visible=10)),
    ("GPS_RAW_INT", dict(time_usec=UINT64_MAX, fix_type=6, lat=-1, lon=-2, alt=-3, eph=65535, epv=65535, vel=65535,
                         cog=65535, satellites_visible=255, alt_ellipsoid=-4, h_acc=1000, v_acc=2000, vel_acc=300,
                         hdg_acc=0xFFFFFFFF, yaw=36000)),
    ("BATTERY_STATUS", dict(id=0, battery_function=1, type=1, temperature=-275, voltages=[4200, 4190, 4180, 65535,
                            65535, 65535, 65535, 65535, 65535, 65535], current_battery=-1, current_consumed=1234,
                            energy_consumed=-1, battery_remaining=-1)),
    ("BATTERY_STATUS", dict(id=2, battery_function=4, type=3, temperature=3500, voltages=[3000] * 10,
                            current_battery=32767, current_consumed=INT32_MIN, energy_consumed=2**31 - 1,
                            battery_remaining=100, time_remaining=3600, charge_state=1, voltages_ext=[1, 2, 0, 4],
                            mode=2, fault_bitmask=0x1FF)),
    ("EXTENDED_SYS_STATE", dict(vtol_state=0, landed_state=1)),
    ("EXTENDED_SYS_STATE", dict(vtol_state=4, landed_state=0)),
    ("SET_MODE", dict(target_system=1, base_mode=1, custom_mode=4)),
    ("SET_MODE", dict(target_system=1, base_mode=209, custom_mode=0)),
    ("MISSION_CLEAR_ALL", dict(target_system=0, target_component=0)),  # all zero: MAVLink 2 keeps one byte
    ("PARAM_SET", dict(target_system=1, target_component=1, param_id=b"RTL_ALT", param_value=1500.0, param_type=9)),
    ("PARAM_REQUEST_READ", dict(target_system=1, target_component=1, param_id=b"", param_index=-1)),
    ("PARAM_REQUEST_READ", dict(target_system=1, target_component=1, param_id=b"FENCE_ENABLE", param_index=-1)),
    ("REQUEST_DATA_STREAM", dict(target_system=1, target_component=1, req_stream_id=0, req_message_rate=4,
                                 start_stop=1)),
    ("SYSTEM_TIME", dict(time_unix_usec=1700000000123456, time_boot_ms=987654)),
    ("TIMESYNC", dict(tc1=0, ts1=-1234567890123456789)),
    ("TIMESYNC", dict(tc1=2**63 - 1, ts1=-(2**63))),  # pymavlink 2.4.50 lacks the target_* extensions
    ("VFR_HUD", dict(airspeed=12.5, groundspeed=11.75, heading=-1, throttle=45, alt=488.25, climb=-0.5)),
    ("RC_CHANNELS", dict(time_boot_ms=42, chancount=8, chan1_raw=1500, chan2_raw=1100, chan3_raw=1900,
                         chan4_raw=1500, chan5_raw=65535, chan8_raw=1000, chan18_raw=2000, rssi=255)),
    ("COMMAND_INT", dict(target_system=1, target_component=1, frame=6, command=192, current=0, autocontinue=0,
                         param1=-1.0, param2=1.0, param3=0.0, param4=float("0.0"), x=473977418, y=85455939, z=50.0)),
    ("MISSION_REQUEST", dict(target_system=255, target_component=190, seq=5)),
    ("MISSION_ITEM_REACHED", dict(seq=9)),
    ("MISSION_SET_CURRENT", dict(target_system=1, target_component=1, seq=2)),
    ("MISSION_REQUEST_LIST", dict(target_system=1, target_component=1, mission_type=0)),
    ("SETUP_SIGNING", dict(target_system=1, target_component=1, secret_key=list(range(200, 232)),
                           initial_timestamp=UINT64_MAX - 1)),
]

SIGNED = [  # (link id, timestamp, message index in MESSAGES)
    (3, 123456789012, 0),
    (255, 2**48 - 1, 5),
]
SECRET_KEY = bytes(range(32))

SENDERS = [(1, 1), (255, 190), (42, 200)]


def exact_float(value):
    """The double value of the float32 nearest to value, so Kotlin's String.toFloat() gets the same bits."""
    return struct.unpack("<f", struct.pack("<f", value))[0]


def class_of(module, name):
    return getattr(module, "MAVLink_%s_message" % name.lower())


def full_values(cls, given):
    """Every field of cls, in declaration order, with given values and zeros elsewhere."""
    values = {}
    for field, ftype, alen in zip(cls.fieldnames, cls.fieldtypes, cls.array_lengths):
        if field in given:
            value = given[field]
        elif ftype == "char":
            value = b""
        elif alen:
            value = [0] * alen
        else:
            value = 0
        values[field] = value
    # Fields that pymavlink's MAVLink 1 dialect lacks are extensions, which MAVLink 1 does not carry.
    unknown = set(given) - set(cls.fieldnames)
    return values, unknown


def json_values(cls, values):
    out = {}
    for field, ftype in zip(cls.fieldnames, cls.fieldtypes):
        value = values[field]
        if ftype == "char":
            out[field] = value.split(b"\x00", 1)[0].decode("utf-8")
        elif ftype in ("float", "double"):
            out[field] = [exact_float(v) for v in value] if isinstance(value, list) else (
                exact_float(value) if ftype == "float" else float(value))
        else:
            out[field] = value
    return json.dumps(out, separators=(",", ":"), ensure_ascii=False)


def encode(module, name, given, sysid, compid, seq, signing=None):
    cls = class_of(module, name)
    values, unknown = full_values(cls, given)
    if module is v2 and unknown:
        raise SystemExit("%s has no fields %s in pymavlink" % (name, unknown))
    msg = cls(**values)
    mav = module.MAVLink(None, srcSystem=sysid, srcComponent=compid)
    mav.seq = seq
    if signing is not None:
        link_id, timestamp = signing
        mav.signing.secret_key = SECRET_KEY
        mav.signing.link_id = link_id
        mav.signing.timestamp = timestamp
        mav.signing.sign_outgoing = True
    wire = msg.pack(mav)
    # Cross-check: pymavlink must parse its own frame back.
    parser = module.MAVLink(None)
    if signing is not None:
        parser.signing.secret_key = SECRET_KEY
    parsed = parser.parse_char(bytearray(wire))
    if parsed is None or parsed.get_type() != name:
        raise SystemExit("pymavlink could not parse back %s" % name)
    return json_values(cls, values), wire.hex()


def message_min_lengths():
    """Payload length without extension fields of every message, from the dialect XML files."""
    lengths = {}
    pending = [os.path.join(os.path.dirname(v2.__file__), "ardupilotmega.xml")]
    seen = set()
    while pending:
        path = pending.pop()
        if path in seen:
            continue
        seen.add(path)
        xml = mavparse.MAVXML(path, mavparse.PROTOCOL_2_0)
        for message in xml.message:
            lengths[message.id] = message.wire_min_length
        pending += [os.path.join(os.path.dirname(path), name) for name in xml.include]
    return lengths


def main():
    os.makedirs(OUT_DIR, exist_ok=True)
    lines = []
    for index, (name, given) in enumerate(MESSAGES):
        sysid, compid = SENDERS[index % len(SENDERS)]
        seq = (index * 37) % 256
        js, hx = encode(v2, name, given, sysid, compid, seq)
        lines.append("\t".join(["2", str(sysid), str(compid), str(seq), name, js, hx]))
        if class_of(v2, name).id <= 255:
            js, hx = encode(v1, name, given, sysid, compid, (seq + 128) % 256)
            lines.append("\t".join(["1", str(sysid), str(compid), str((seq + 128) % 256), name, js, hx]))
    for link_id, timestamp, index in SIGNED:
        name, given = MESSAGES[index]
        js, hx = encode(v2, name, given, 7, 1, 200, signing=(link_id, timestamp))
        lines.append("\t".join(["2", "7", "1", "200", name, js, hx]))
    with open(os.path.join(OUT_DIR, "pymavlink-vectors.tsv"), "w", encoding="utf-8") as f:
        f.write("# version\tsysid\tcompid\tseq\tmessage\tfields\twire hex   (tools/gen_mavlink_vectors.py)\n")
        f.write("\n".join(lines) + "\n")

    min_lengths = message_min_lengths()
    rows = []
    for msg_id, cls in sorted(v2.mavlink_map.items()):
        rows.append("\t".join([str(msg_id), cls.msgname, str(cls.crc_extra), str(min_lengths[msg_id]),
                               str(cls.unpacker.size)]))
    with open(os.path.join(OUT_DIR, "pymavlink-messages.tsv"), "w", encoding="utf-8") as f:
        f.write("# id\tname\tcrc_extra\tpayload length without extensions\twith extensions\n")
        f.write("\n".join(rows) + "\n")
    print("wrote %d vectors and %d message layouts to %s" % (len(lines), len(rows), os.path.normpath(OUT_DIR)),
          file=sys.stderr)


if __name__ == "__main__":
    main()
