#!/usr/bin/env bash
# Fleet scale: one Pod GroundStation hearing 250 vehicles simulated in 3 other JVMs (1 Hz HEARTBEAT,
# 10 Hz GLOBAL_POSITION_INT, 5 Hz ATTITUDE each), commanding one vehicle after another every 50 ms.
# Reports the station process's CPU, command round trips and vehicles falsely marked lost.
#
#   bench/fleet.sh                  10 minutes measured after 30 s of warm-up (the BENCHMARKS.md figure)
#   bench/fleet.sh --quick          a 1-minute smoke run (figures not meaningful)
#   bench/fleet.sh --duration 3m    any other option goes to pod.bench.fleet.FleetBenchKt
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

settings=(--vehicles 250 --senders 3 --duration 10m --warmup 30s --command-every 50ms)
if [ "${1:-}" = "--quick" ]; then settings=(--vehicles 250 --senders 3 --duration 45s --warmup 10s --command-every 50ms); shift; fi

results="$root/bench/target/results"
bench/machine-info.sh 2>/dev/null || true
if [ "${SKIP_BUILD:-}" != "1" ]; then
  echo "== build"
  ./mvnw -B -ntp -o -Dkotlin.compiler.daemon=false -Pbench -pl bench -am package -DskipTests
fi
mkdir -p "$results"
cp="$root/bench/target/pod-bench-0.1.0-SNAPSHOT.jar:$root/bench/target/lib/*"
echo "== fleet scale"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
timeout 1800 java -Xms512m -Xmx512m -cp "$cp" pod.bench.fleet.FleetBenchKt "${settings[@]}" \
  --json "$results/fleet.json" "$@" | tee "$results/fleet.md"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
