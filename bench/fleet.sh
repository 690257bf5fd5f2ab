#!/usr/bin/env bash
# Fleet scale: one Pod GroundStation hearing 250 vehicles simulated in 3 other JVMs (1 Hz HEARTBEAT,
# 10 Hz GLOBAL_POSITION_INT, 5 Hz ATTITUDE each), commanding one vehicle after another every 50 ms.
# Reports the station process's CPU, command round trips and vehicles falsely marked lost.
#
#   bench/fleet.sh                  10 minutes measured after 30 s of warm-up (the BENCHMARKS.md figure)
#   bench/fleet.sh --quick          a 1-minute smoke run (figures not meaningful)
#   bench/fleet.sh --duration 3m    any other option goes to pod.bench.fleet.FleetBenchKt
#   bench/fleet.sh --vehicles 1000 --links 4 --senders 4   1,000 vehicles on 4 stations (one udpin link each) in one JVM
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"

if $quick; then
  settings=(--vehicles 250 --senders 3 --duration 45s --warmup 10s --command-every 50ms)
else
  settings=(--vehicles 250 --senders 3 --duration 10m --warmup 30s --command-every 50ms)
fi

machine_info
build_bench
echo "== fleet scale"
echo "load average before: $(load)"
timeout 1800 java -Xms512m -Xmx512m -cp "$cp" pod.bench.fleet.FleetBenchKt "${settings[@]}" \
  --json "$results/fleet.json" "$@" | tee "$results/fleet.md"
echo "load average after: $(load)"
