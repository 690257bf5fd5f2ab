"""The Python peer of `pod arm --sysid 1` for bench/start.sh: pymavlink waits for the vehicle's
heartbeat on udpin:127.0.0.1:PORT, sends MAV_CMD_COMPONENT_ARM_DISARM, and waits for its accepted
COMMAND_ACK and a heartbeat that says armed, as `pod arm` does. Prints one JSON line: the vehicle's
answer time (from the socket being open to armed) and the import time, both from perf_counter, so
that the script's process time minus the answer is Python's own overhead."""
import json
import sys
import time

t_start = time.perf_counter()
from pymavlink import mavutil  # noqa: E402  (timed: the import is Python's start-up cost)

t_imported = time.perf_counter()
port = int(sys.argv[1])
m = mavutil.mavlink_connection(f"udpin:127.0.0.1:{port}", source_system=255, source_component=190)
t_open = time.perf_counter()
if m.wait_heartbeat(timeout=10) is None:
    sys.exit("no heartbeat within 10 s")
m.mav.command_long_send(m.target_system, m.target_component, mavutil.mavlink.MAV_CMD_COMPONENT_ARM_DISARM, 0, 1, 0, 0, 0, 0, 0, 0)
acked = armed = False
deadline = time.monotonic() + 10
while not (acked and armed):
    if time.monotonic() > deadline:
        sys.exit(f"no answer within 10 s (acked {acked}, armed {armed})")
    msg = m.recv_match(type=["COMMAND_ACK", "HEARTBEAT"], blocking=True, timeout=1)
    if msg is None or msg.get_srcSystem() != m.target_system:
        continue
    if msg.get_type() == "COMMAND_ACK" and msg.command == mavutil.mavlink.MAV_CMD_COMPONENT_ARM_DISARM:
        if msg.result != mavutil.mavlink.MAV_RESULT_ACCEPTED:
            sys.exit(f"arm refused: result {msg.result}")
        acked = True
    elif msg.get_type() == "HEARTBEAT" and acked and msg.base_mode & mavutil.mavlink.MAV_MODE_FLAG_SAFETY_ARMED:
        armed = True
t_done = time.perf_counter()
m.close()
print(json.dumps({"answer_s": t_done - t_open, "import_s": t_imported - t_start}))
