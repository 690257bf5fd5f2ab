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
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"

if $quick; then
  settings=(--counts 1,10,100 --rounds 20,5,3 --warmup 3,2,1 --lossy-rounds 3 --lossy-warmup 1 --pod-warmup 50)
else
  settings=(--counts 1,10,100 --rounds 200,50,20 --warmup 20,5,3 --lossy-rounds 30 --lossy-warmup 3 --pod-warmup 200)
fi

machine_info

build_bench

echo "== Python peers (pymavlink)"
tools/python-peers.sh
echo "Python $(.venv/bin/python -c 'import platform; print(platform.python_version())'), pymavlink $(.venv/bin/python -c 'import importlib.metadata as m; print(m.version("pymavlink"))')"

echo "== command round trip"
# Other work on this machine shows in the figures: say how busy it was.
echo "load average before: $(load)"
# Every wait is bounded inside the harness; this bounds the whole in case of a bug.
timeout 1800 java -Xms512m -Xmx512m -cp "$cp" pod.bench.command.CommandBenchKt "${settings[@]}" \
  --python .venv/bin/python --script bench/pymavlink_command.py \
  --peer-log "$results/command-peers.log" \
  --json "$results/command.json" --markdown "$results/command.md" "$@" \
  || echo "command harness exited with $?"
echo "load average after: $(load)"
