#!/usr/bin/env python3
"""pymavlink as a ground station commanding a simulated fleet: the COMMAND_LONG -> COMMAND_ACK
round trip, every vehicle at once, the peer of Pod's CommandService in the command benchmark
(pod.bench.command.CommandBenchKt drives this script; bench/command.sh runs both).

One mavutil UDP connection listens on 127.0.0.1 (port 0 unless --port: the port it got is
printed). Every vehicle's address is learned from its HEARTBEAT: mavutil's udpin writes every
message to every client it has heard and keeps no sender per datagram, so the script reads with
recvfrom() on the connection's socket and hands each datagram to the connection's parser and
post_message (what recv_msg does), and sends each vehicle's command with sendto() to that
vehicle's own address, encoded by the connection's MAVLink 2 encoder (sequence numbers counted as
mav.send does). Like a real ground station it sends its own HEARTBEAT to every vehicle once a second.

Per round: MAV_CMD_SET_MESSAGE_INTERVAL (511), SYS_STATUS at 1,000,000 us (the vehicles' own rate),
to every vehicle in one loop, then one select() loop reads every datagram through mavutil
(parse_char: parse and CRC_EXTRA check; post_message: per-system bookkeeping) until each vehicle's COMMAND_ACK came;
a vehicle that has not answered within --resend-ms of the last send gets the command again with
confirmation + 1, and after --give-up-s without an answer the command counts as failed. Latency:
from the first send of a vehicle's command to the arrival of its ack; makespan: from the round's
start to the last ack. Rounds are --gap-ms apart (datagrams arriving then are read and dropped).

stdout, one JSON object a line: {"event": "ready", "port": P}, {"event": "discovered", ...},
{"event": "measuring"} after the warm-up rounds, one {"event": "round", ...} per measured round (latencies as a comma-separated string, so that the
object stays flat), {"event": "summary", ...} (with the CPU time of the measured rounds) and {"event": "done"}; {"event": "error", ...} on
failure. Every wait is bounded.
"""

import argparse
import json
import os
import select
import statistics
import sys
import time

os.environ.setdefault("MAVLINK20", "1")  # encode MAVLink 2, as Pod does
from pymavlink import mavutil  # noqa: E402

MAV_CMD_SET_MESSAGE_INTERVAL = 511
SYS_STATUS = 1
MAV_RESULT_ACCEPTED = 0
MAV_RESULT_IN_PROGRESS = 5
MAV_TYPE_GCS = 6


def emit(**fields):
    print(json.dumps(fields), flush=True)


def percentile(values, p):
    """Nearest-rank percentile, as the Kotlin harness computes it."""
    if not values:
        return float("nan")
    ordered = sorted(values)
    rank = min(len(ordered), max(1, -(-p * len(ordered) // 100)))
    return ordered[int(rank) - 1]


class Station:
    def __init__(self, port):
        self.conn = mavutil.mavlink_connection(f"udpin:127.0.0.1:{port}", source_system=255, source_component=190)
        self.sock = self.conn.port
        self.mav = self.conn.mav
        self.addresses = {}  # system id -> (host, port) its HEARTBEATs come from
        self.next_heartbeat = 0.0

    @property
    def port(self):
        return self.sock.getsockname()[1]

    def send(self, address, message):
        buf = message.pack(self.mav)
        self.sock.sendto(buf, address)
        # What MAVLink.send does after writing.
        self.mav.seq = (self.mav.seq + 1) % 256
        self.mav.total_packets_sent += 1
        self.mav.total_bytes_sent += len(buf)

    def heartbeat_if_due(self, now):
        if now < self.next_heartbeat:
            return
        self.next_heartbeat = now + 1.0
        message = self.mav.heartbeat_encode(MAV_TYPE_GCS, mavutil.mavlink.MAV_AUTOPILOT_INVALID, 0, 0, mavutil.mavlink.MAV_STATE_ACTIVE)
        for address in self.addresses.values():
            self.send(address, message)

    def read(self, timeout, on_message):
        """Waits up to timeout seconds for datagrams, then reads every one queued."""
        ready, _, _ = select.select([self.sock], [], [], max(0.0, timeout))
        if not ready:
            return
        while True:
            try:
                data, address = self.sock.recvfrom(65535)
            except BlockingIOError:
                return
            # What mavudp.recv_msg does with a datagram, keeping the sender's address, which
            # mavudp (2.4.50) does not record per datagram when listening.
            self.conn.pre_message()
            if self.conn.first_byte:
                self.conn.auto_mavlink_version(data)
            message = self.mav.parse_char(data)
            if message is not None:
                self.conn.post_message(message)
                on_message(message, address)

    def discover(self, count, limit):
        start = time.perf_counter()

        def on_message(message, address):
            if message.get_type() == "HEARTBEAT" and message.type != MAV_TYPE_GCS:
                self.addresses[message.get_srcSystem()] = address

        while len(self.addresses) < count:
            now = time.perf_counter()
            if now - start > limit:
                return None
            self.heartbeat_if_due(now)
            self.read(min(0.1, limit - (now - start)), on_message)
        return time.perf_counter() - start

    def command(self, system, confirmation):
        return self.mav.command_long_encode(
            system, 1, MAV_CMD_SET_MESSAGE_INTERVAL, confirmation,
            float(SYS_STATUS), 1_000_000.0, 0, 0, 0, 0, 0)

    def round(self, resend, give_up):
        """One round to every vehicle; returns (latencies_us, makespan_us, failures, sends)."""
        pending = {}  # system id -> [first send, last send, attempts]
        latencies = []
        sends = 0
        start = time.perf_counter()
        last_ack = start
        for system, address in self.addresses.items():
            self.send(address, self.command(system, 0))
            now = time.perf_counter()
            pending[system] = [now, now, 1]
            sends += 1

        def on_message(message, address):
            nonlocal last_ack
            if message.get_type() != "COMMAND_ACK" or message.command != MAV_CMD_SET_MESSAGE_INTERVAL:
                return
            system = message.get_srcSystem()
            state = pending.get(system)
            if state is None or message.target_system not in (0, 255):
                return  # a late duplicate, or meant for someone else
            if message.result == MAV_RESULT_IN_PROGRESS:
                state[1] = time.perf_counter()  # keep waiting without resending
                return
            now = time.perf_counter()
            del pending[system]
            if message.result == MAV_RESULT_ACCEPTED:
                latencies.append((now - state[0]) * 1e6)
                last_ack = now

        while pending:
            now = time.perf_counter()
            self.heartbeat_if_due(now)
            for system, state in list(pending.items()):
                if now - state[0] >= give_up:
                    del pending[system]
                elif now - state[1] >= resend:
                    self.send(self.addresses[system], self.command(system, min(state[2], 255)))
                    state[1] = time.perf_counter()
                    state[2] += 1
                    sends += 1
            if not pending:
                break
            wake = min(min(s[1] + resend, s[0] + give_up) for s in pending.values())
            self.read(min(wake, self.next_heartbeat) - time.perf_counter(), on_message)
        failures = len(self.addresses) - len(latencies)  # given up on, or answered with a refusal
        end = last_ack if latencies else time.perf_counter()
        return latencies, (end - start) * 1e6, failures, sends

    def idle(self, seconds):
        """Reads and drops what arrives for this long (telemetry, late acks); keeps the heartbeat going."""
        until = time.perf_counter() + seconds
        while True:
            now = time.perf_counter()
            if now >= until:
                return
            self.heartbeat_if_due(now)
            self.read(until - now, lambda message, address: None)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--port", type=int, default=0)
    parser.add_argument("--count", type=int, required=True, help="vehicles to wait for and command")
    parser.add_argument("--rounds", type=int, required=True)
    parser.add_argument("--warmup", type=int, default=0, help="rounds run first and not reported")
    parser.add_argument("--gap-ms", type=float, default=20)
    parser.add_argument("--resend-ms", type=float, default=500)
    parser.add_argument("--give-up-s", type=float, default=10)
    parser.add_argument("--discover-s", type=float, default=30)
    args = parser.parse_args()
    if not (1 <= args.count <= 254 and 1 <= args.rounds <= 100_000 and 0 <= args.warmup <= 100_000):
        raise SystemExit("count must be in 1..254, rounds in 1..100000, warmup in 0..100000")

    station = Station(args.port)
    emit(event="ready", port=station.port)
    seconds = station.discover(args.count, args.discover_s)
    if seconds is None:
        emit(event="error", message=f"{len(station.addresses)} of {args.count} vehicles discovered within {args.discover_s} s")
        return 1
    emit(event="discovered", count=len(station.addresses), seconds=round(seconds, 3))

    all_latencies, makespans, failures, sends = [], [], 0, 0
    cpu = 0.0
    for r in range(args.warmup + args.rounds):
        if r == args.warmup:
            emit(event="measuring")
            cpu = time.process_time()
        latencies, makespan, failed, sent = station.round(args.resend_ms / 1000, args.give_up_s)
        if r >= args.warmup:
            emit(event="round", round=r - args.warmup, makespan_us=round(makespan, 1), failures=failed, sends=sent,
                 latencies_us=",".join(f"{x:.1f}" for x in latencies))
            all_latencies += latencies
            makespans.append(makespan)
            failures += failed
            sends += sent
        station.idle(args.gap_ms / 1000)
    cpu = time.process_time() - cpu
    emit(event="summary", cpu_seconds=round(cpu, 6), commands=args.rounds * args.count, acknowledged=len(all_latencies), failures=failures,
         resends=sends - args.rounds * args.count,
         median_ms=percentile(all_latencies, 50) / 1000, p90_ms=percentile(all_latencies, 90) / 1000,
         p99_ms=percentile(all_latencies, 99) / 1000, max_ms=max(all_latencies, default=float("nan")) / 1000,
         makespan_median_ms=statistics.median(makespans) / 1000,
         commands_per_s=len(all_latencies) / (sum(makespans) / 1e6))
    emit(event="done")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Exception as e:  # reported, not swallowed: the harness prints it
        emit(event="error", message=f"{type(e).__name__}: {e}")
        raise
