#!/usr/bin/env bash
# Builds the benchmarks and runs the command round-trip harness (pod.bench.command.CommandBenchKt):
# Pod's GroundStation and pymavlink (bench/pymavlink_command.py) as ground station, each sending
# MAV_CMD_SET_MESSAGE_INTERVAL to 1, 10 and 100 simulated vehicles at once (vehicles in a JVM of
# their own, loopback UDP) and waiting for every COMMAND_ACK, round after round; then 10 vehicles
# each behind a seeded relay dropping 30 % each way. Prints both side by side; results land in
# bench/target/results/command.json and command.md (stderr of the peers in command-peers.log).
#
#   bench/command.sh           the full run: 200 / 50 / 20 rounds, 30 lossy rounds; about 3 minutes on 2 cores
#   bench/command.sh --quick   a 1-minute smoke run with a few rounds per case (figures not meaningful)
# Any further option goes to the harness (a later option wins), e.g. --stations POD or --gap 0ms.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

quick=false
if [ "${1:-}" = "--quick" ]; then quick=true; shift; fi

if $quick; then
  settings=(--counts 1,10,100 --rounds 20,5,3 --warmup 3,2,1 --lossy-rounds 3 --lossy-warmup 1 --pod-warmup 50)
else
  settings=(--counts 1,10,100 --rounds 200,50,20 --warmup 20,5,3 --lossy-rounds 30 --lossy-warmup 3 --pod-warmup 200)
fi

results="$root/bench/target/results"
echo "== machine"
echo "cores: $(nproc); CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'); memory: $(free -g | awk '/^Mem:/ {print $2 " GiB"}')"
echo "JDK: $(java -version 2>&1 | head -2 | tail -1)"
echo "OS: $(. /etc/os-release 2>/dev/null && echo "$PRETTY_NAME"), kernel $(uname -r)"
echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo '?')$(git diff --quiet 2>/dev/null || echo ' (with uncommitted changes)')"

echo "== build"
./mvnw -B -ntp -o -Pbench -pl bench -am package -DskipTests
mkdir -p "$results"
cp="$root/bench/target/pod-bench-0.1.0-SNAPSHOT.jar:$root/bench/target/lib/*"

echo "== Python peers (pymavlink)"
tools/python-peers.sh
echo "Python $(.venv/bin/python -c 'import platform; print(platform.python_version())'), pymavlink $(.venv/bin/python -c 'import importlib.metadata as m; print(m.version("pymavlink"))')"

echo "== command round trip"
# Other work on this machine shows in the figures: say how busy it was.
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
# Every wait is bounded inside the harness; this bounds the whole in case of a bug.
timeout 1800 java -Xms512m -Xmx512m -cp "$cp" pod.bench.command.CommandBenchKt "${settings[@]}" \
  --python .venv/bin/python --script bench/pymavlink_command.py \
  --peer-log "$results/command-peers.log" \
  --json "$results/command.json" --markdown "$results/command.md" "$@" \
  || echo "command harness exited with $?"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
