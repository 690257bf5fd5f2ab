#!/usr/bin/env python3
"""Puts the results of one bench/run.sh side by side as Markdown tables (standard library only).

Inputs, all written by the same run: JMH's JSON (-rf json), pymavlink_decode.py's --json and the
ingest harness's --json. Missing or failed parts show as "n/a" instead of stopping the summary.
"""

import argparse
import json
import os

MESSAGES = ["HEARTBEAT", "SYS_STATUS", "ATTITUDE", "GLOBAL_POSITION_INT", "MISSION_CURRENT"]

# JMH benchmark method -> column title, in table order.
JVM_COLUMNS = [
    ("pod.bench.PodDecodeBenchmark.feedAndDecode", "Pod: FrameDecoder.feed + MessageCodec.decode"),
    ("pod.bench.PayloadDecodeBenchmark.podCodec", "Pod: MessageCodec.decode (payload only)"),
    ("pod.bench.PayloadDecodeBenchmark.dronefleetReflective", "io.dronefleet: ReflectionPayloadDeserializer (payload only)"),
    ("pod.bench.DronefleetStreamBenchmark.connectionNext", "io.dronefleet: MavlinkConnection.next (frame + payload)"),
]
PY_COLUMNS = [
    ("parse_char", "pymavlink: parse_char (stream)"),
    ("parse_buffer", "pymavlink: parse_buffer (stream)"),
    ("decode", "pymavlink: decode (one frame)"),
]


def load(path):
    if not path or not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def fmt_rate(value, error=None):
    if value is None:
        return "n/a"
    # JMH writes the error as the string "NaN" when it had too few iterations to compute one.
    if isinstance(error, (int, float)) and error == error:
        return f"{value:,.0f} ± {error:,.0f}"
    return f"{value:,.0f}"


def jvm_scores(jmh):
    """(benchmark, message) -> (score, error, allocated bytes per op or None)."""
    scores = {}
    for entry in jmh or []:
        message = entry.get("params", {}).get("message")
        metric = entry["primaryMetric"]
        secondary = entry.get("secondaryMetrics", {})
        # JMH 1.37 names it "gc.alloc.rate.norm"; older versions prefix a middle dot.
        alloc = (secondary.get("gc.alloc.rate.norm") or secondary.get("\u00b7gc.alloc.rate.norm") or {}).get("score")
        scores[(entry["benchmark"], message)] = (metric["score"], metric.get("scoreError"), alloc)
    return scores


def decode_table(jmh, py):
    """One row per decoder, one column per message: the implementations side by side."""
    jvm = jvm_scores(jmh)
    pyr = {(r["api"], r["message"]): r["framesPerSecond"] for r in (py or {}).get("results", [])}
    lines = [
        "| decoder | " + " | ".join(MESSAGES) + " |",
        "|---|" + "---:|" * len(MESSAGES),
    ]
    for bench, title in JVM_COLUMNS:
        cells = [fmt_rate(*jvm.get((bench, m), (None, None, None))[:2]) for m in MESSAGES]
        lines.append(f"| {title} | " + " | ".join(cells) + " |")
    for api, title in PY_COLUMNS:
        cells = [fmt_rate(pyr.get((api, m))) for m in MESSAGES]
        lines.append(f"| {title} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def allocation_table(jmh):
    """Bytes allocated per decoded frame (JMH -prof gc), where measured."""
    jvm = jvm_scores(jmh)
    if not any(v[2] is not None for v in jvm.values()):
        return None
    lines = [
        "| decoder | " + " | ".join(MESSAGES) + " |",
        "|---|" + "---:|" * len(MESSAGES),
    ]
    for bench, title in JVM_COLUMNS:
        cells = []
        for m in MESSAGES:
            alloc = jvm.get((bench, m), (None, None, None))[2]
            cells.append("n/a" if alloc is None else f"{alloc:,.0f}")
        lines.append(f"| {title} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def ratio_lines(jmh, py):
    """Pod's full path against the others, for the messages all of them measured."""
    jvm = {(e["benchmark"], e.get("params", {}).get("message")): e["primaryMetric"]["score"] for e in jmh or []}
    pyr = {(r["api"], r["message"]): r["framesPerSecond"] for r in (py or {}).get("results", [])}
    out = []
    for message in MESSAGES:
        pod = jvm.get(("pod.bench.PodDecodeBenchmark.feedAndDecode", message))
        reflective = jvm.get(("pod.bench.PayloadDecodeBenchmark.dronefleetReflective", message))
        python = pyr.get(("parse_char", message))
        parts = []
        if pod and reflective:
            parts.append(f"{pod / reflective:,.0f}× io.dronefleet's reflective payload decoder")
        if pod and python:
            parts.append(f"{pod / python:,.0f}× pymavlink parse_char")
        if parts:
            out.append(f"- {message}: Pod's full path (frame + payload) decodes " + ", ".join(parts) + ".")
    return "\n".join(out)


def ingest_table(ingest):
    if not ingest:
        return "(no ingest results)"
    by_load = {}
    for row in ingest:
        by_load.setdefault(row["load"], {})[row["target"]] = row
    lines = [
        "| offered load | offered (dgram/s) | Pod delivered (dgram/s) | Pod loss | Pod CPU (µs/dgram) "
        "| NIO delivered (dgram/s) | NIO loss | NIO CPU (µs/dgram) |",
        "|---|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for load, targets in by_load.items():
        pod, nio = targets.get("POD"), targets.get("NIO")
        offered = (pod or nio)["offered"]

        def cells(row):
            if row is None:
                return ["n/a"] * 3
            loss = f"{row['lossPercent']:.1f} %"
            if row["runs"] > 1:
                loss += f" ({row['lossMin']:.1f}–{row['lossMax']:.1f})"
            return [f"{row['delivered']:,.0f}", loss, f"{row['cpuMicrosPerDatagram']:.2f}"]

        lines.append(f"| {load} | {offered:,.0f} | " + " | ".join(cells(pod) + cells(nio)) + " |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--jmh")
    parser.add_argument("--pymavlink")
    parser.add_argument("--ingest")
    args = parser.parse_args()
    jmh, py, ingest = load(args.jmh), load(args.pymavlink), load(args.ingest)
    print("### Decode, one frame per operation (frames/s on one thread, higher is better; JMH ± is its 99.9 % interval)\n")
    print(decode_table(jmh, py))
    ratios = ratio_lines(jmh, py)
    if ratios:
        print()
        print(ratios)
    allocations = allocation_table(jmh)
    if allocations:
        print("\n### Allocation per decoded frame (bytes/op, JMH -prof gc)\n")
        print(allocations)
    print("\n### UDP ingest on loopback, GLOBAL_POSITION_INT from 3 vehicles\n")
    print(ingest_table(ingest))


if __name__ == "__main__":
    main()
