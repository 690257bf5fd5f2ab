#!/usr/bin/env bash
# Builds the benchmarks and runs all of them, printing every result and a side-by-side summary:
#   1. JMH decode benchmarks: Pod, io.dronefleet (reflective payload decoder, MavlinkConnection)
#   2. pymavlink decoding the same datagrams
#   3. UDP ingest on loopback: Pod GroundStation vs a bare NIO receiver, at several offered rates
# Sized for a 2-core machine: about 6.5 minutes in all. Results land in bench/target/results/.
#
#   bench/run.sh           the full run (the figures in BENCHMARKS.md)
#   bench/run.sh --quick   a 1.5-minute smoke run with short settings (figures not meaningful)
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"

if $quick; then
  jmh_settings=(-f 1 -wi 1 -w 1s -i 2 -r 1s)
  py_settings=(--rounds 1 --frames 20000 --seconds 1)
  ingest_settings=(--count 50000 --repeats 1 --rates 50000,max)
else
  # One fork, 3 x 2 s warm-up, 5 x 2 s measurement: ~17 s per benchmark and parameter, 11 of them.
  jmh_settings=(-f 1 -wi 3 -w 2s -i 5 -r 2s)
  py_settings=(--rounds 3 --frames 100000 --seconds 2)
  ingest_settings=(--count 200000 --repeats 3 --rates 20000,50000,100000,max)
fi

machine_info

build_bench
# Every run starts from an empty results folder: the summary reads what this run wrote.
rm -rf "$results"
mkdir -p "$results"

echo "== fixtures (io.dronefleet-encoded MAVLink 2 datagrams, decoded by every benchmark below)"
java -cp "$cp" pod.bench.WriteFixturesKt "$results/fixtures"

echo "== JMH decode benchmarks (ops/s = frames/s, one frame per op)"
# A failing benchmark (e.g. a codec that throws) is reported by JMH and the run goes on.
timeout 600 java -cp "$cp" org.openjdk.jmh.Main "${jmh_settings[@]}" \
  -jvmArgs "-Xms512m -Xmx512m" -prof gc -rf json -rff "$results/jmh.json" 'pod\.bench\..*Benchmark' \
  || echo "JMH exited with $? (results so far are kept)"

echo "== pymavlink decode (same datagrams)"
tools/python-peers.sh
timeout 300 .venv/bin/python bench/pymavlink_decode.py --fixtures "$results/fixtures" \
  --messages HEARTBEAT,SYS_STATUS,ATTITUDE,GLOBAL_POSITION_INT,MISSION_CURRENT \
  "${py_settings[@]}" --json "$results/pymavlink.json" \
  || echo "pymavlink benchmark exited with $?"

echo "== UDP ingest on loopback (Pod GroundStation vs bare NIO receiver)"
timeout 600 java -Xms512m -Xmx512m -cp "$cp" pod.bench.IngestBenchKt "${ingest_settings[@]}" \
  --json "$results/ingest.json" \
  || echo "ingest harness exited with $?"

echo "== summary"
python3 bench/summarize.py --jmh "$results/jmh.json" --pymavlink "$results/pymavlink.json" \
  --ingest "$results/ingest.json" | tee "$results/summary.md"
