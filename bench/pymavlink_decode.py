#!/usr/bin/env python3
"""pymavlink decode rate on the very datagrams the JMH benchmarks decode.

Reads <fixtures>/<NAME>.bin (written by pod.bench.WriteFixturesKt) and, for each message, times
three public APIs of pymavlink's generated MAVLink 2 ardupilotmega dialect, one datagram per call:

  parse_char(datagram)    the stream parser (what mavutil connections call per received datagram);
                          returns the first complete frame of what it was fed
  parse_buffer(datagram)  the same parser, returning every frame of the chunk (one more call inside)
  decode(frame)           the frame decoder under the stream parser: one whole frame, no
                          resynchronisation; not a stream API, listed as the floor of pymavlink's cost

Every API checks CRC_EXTRA (and fastcrc is used when installed, as pymavlink does by itself).
Each measurement is bounded: rounds of at most --frames calls or --seconds, whichever ends first;
the first round is a warm-up, the median of the others is reported in frames per second.
"""

import argparse
import json
import os
import platform
import statistics
import sys
import time

# Import the MAVLink 2 dialect module directly: mavutil would pick v1 unless MAVLINK20 is set.
from pymavlink.dialects.v20 import ardupilotmega as dialect

MESSAGE_TYPES = {
    "HEARTBEAT": "HEARTBEAT",
    "SYS_STATUS": "SYS_STATUS",
    "ATTITUDE": "ATTITUDE",
    "GLOBAL_POSITION_INT": "GLOBAL_POSITION_INT",
    "MISSION_CURRENT": "MISSION_CURRENT",
}


def make_parser():
    """A fresh MAVLink parser with no file behind it, strict (not robust) parsing as by default."""
    return dialect.MAVLink(None, srcSystem=255, srcComponent=190)


def time_parse_char(datagram, frames, seconds):
    mav = make_parser()
    parse = mav.parse_char
    deadline = time.perf_counter() + seconds
    done = 0
    start = time.perf_counter()
    # Check the clock every 1000 calls so timing costs nothing per frame.
    while done < frames and time.perf_counter() < deadline:
        for _ in range(1000):
            if parse(datagram) is None:
                raise SystemExit("parse_char returned no message")
        done += 1000
    return done / (time.perf_counter() - start)


def time_parse_buffer(datagram, frames, seconds):
    mav = make_parser()
    parse = mav.parse_buffer
    deadline = time.perf_counter() + seconds
    done = 0
    start = time.perf_counter()
    while done < frames and time.perf_counter() < deadline:
        for _ in range(1000):
            if not parse(datagram):
                raise SystemExit("parse_buffer returned no message")
        done += 1000
    return done / (time.perf_counter() - start)


def time_decode(datagram, frames, seconds):
    mav = make_parser()
    decode = mav.decode
    frame = bytearray(datagram)
    deadline = time.perf_counter() + seconds
    done = 0
    start = time.perf_counter()
    while done < frames and time.perf_counter() < deadline:
        for _ in range(1000):
            decode(frame)
        done += 1000
    return done / (time.perf_counter() - start)


APIS = {
    "parse_char": time_parse_char,
    "parse_buffer": time_parse_buffer,
    "decode": time_decode,
}


def check_fixture(name, datagram):
    """Decodes once and checks the type: pymavlink vouches for the bytes (CRC_EXTRA included)."""
    message = make_parser().parse_char(datagram)
    if message is None or message.get_type() != MESSAGE_TYPES[name]:
        raise SystemExit(f"{name}: pymavlink decoded {message!r}")
    return message


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--fixtures", required=True, help="directory holding <NAME>.bin datagrams")
    parser.add_argument("--messages", default="HEARTBEAT,GLOBAL_POSITION_INT")
    parser.add_argument("--apis", default=",".join(APIS))
    parser.add_argument("--frames", type=int, default=100_000, help="upper bound of calls per round")
    parser.add_argument("--seconds", type=float, default=2.0, help="upper bound of time per round")
    parser.add_argument("--rounds", type=int, default=5, help="measured rounds (after one warm-up round)")
    parser.add_argument("--json", help="write results here")
    args = parser.parse_args()

    import pymavlink
    try:
        import fastcrc  # noqa: F401  (only reported: pymavlink picks it up by itself)
        crc = "fastcrc"
    except ImportError:
        crc = "pure-Python CRC"
    print(f"pymavlink {getattr(pymavlink, '__version__', '?')} on Python {platform.python_version()} "
          f"({platform.python_implementation()}), dialect ardupilotmega v2, {crc}")

    results = []
    for name in args.messages.split(","):
        with open(os.path.join(args.fixtures, f"{name}.bin"), "rb") as f:
            datagram = f.read()
        message = check_fixture(name, datagram)
        print(f"{name}: {len(datagram)} bytes, decodes to {message}")
        for api in args.apis.split(","):
            timer = APIS[api]
            timer(datagram, args.frames, args.seconds)  # warm-up round
            rates = [timer(datagram, args.frames, args.seconds) for _ in range(args.rounds)]
            median = statistics.median(rates)
            print(f"  {api:<13} {median:>12,.0f} frames/s  (median of {len(rates)}, "
                  f"min {min(rates):,.0f}, max {max(rates):,.0f})")
            results.append({"message": name, "api": api, "framesPerSecond": median,
                            "min": min(rates), "max": max(rates), "rounds": len(rates)})

    if args.json:
        with open(args.json, "w") as f:
            json.dump({"python": platform.python_version(), "crc": crc, "results": results}, f, indent=2)
        print(f"wrote {args.json}")


if __name__ == "__main__":
    sys.exit(main())
