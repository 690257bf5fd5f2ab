#!/usr/bin/env bash
# Builds the benchmarks and runs issue 14's queue benchmark (pod.bench.queue.QueueBenchKt): the
# time from a change of the element being flown to the simulated ArduCopter steering for the new
# point — the mission queue's replaceCurrent (one DO_REPOSITION in GUIDED) against re-uploading the
# whole equivalent mission in AUTO plus MISSION_SET_CURRENT — on real UDP sockets on 127.0.0.1,
# straight and through a relay with 50 ms delay each way (and 20 % loss each way), the simulator in
# real time. Results land in bench/target/results/queue.json and queue.md.
#
#   bench/queue.sh              the full run: N = 10 and 100, loopback, 100 ms RTT, 100 ms RTT + 20 % loss; ~16 minutes
#   bench/queue.sh --quick      a 1-minute smoke run: N = 10, loopback and 100 ms RTT, 3 changes each
#   any other option goes to the harness (a later option wins), e.g. --conditions LOOPBACK,RTT100
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"

if $quick; then
  settings=(--sizes 10 --conditions LOOPBACK,RTT100 --reps 3 --warmup 1)
else
  settings=(--sizes 10,100 --conditions LOOPBACK,RTT100,RTT100_LOSS20 --reps 30 --warmup 5 --lossy-reps 10)
fi

machine_info

build_bench

echo "== queue change latency"
# Every change is bounded inside the harness (60 s); this bounds the whole in case of a bug.
timeout 3600 java -Xms512m -Xmx512m -cp "$cp" pod.bench.queue.QueueBenchKt "${settings[@]}" \
  --json "$results/queue.json" --markdown "$results/queue.md" "$@" \
  || echo "queue harness exited with $?"
