#!/usr/bin/env bash
# Builds the benchmarks and runs the mission-transfer harness (pod.bench.mission.MissionBenchKt):
# Pod's GroundStation and MAVSDK 4.1 (MissionRaw, bench/mavsdk_mission.py) as ground station,
# uploading into and downloading from a simulated vehicle through a seeded lossy UDP relay on
# loopback. Prints the loopback floor, a grid of sizes x loss x flavour, and success rates at
# 30 % loss. Results land in bench/target/results/mission.json and mission.md.
#
#   bench/mission.sh                              the full run, PX4 flavour: about 20 minutes on 2 cores
#   bench/mission.sh --flavours PX4,ARDUPILOT     both flavours: about twice as long (any option goes to the harness)
#   bench/mission.sh --flavours ARDUPILOT --json bench/target/results/mission-ardupilot.json \
#     --markdown bench/target/results/mission-ardupilot.md   ArduPilot alone, next to a PX4 run's results
#   bench/mission.sh --quick                      a 3-minute smoke run: PX4, 10 and 100 items, 0 and 30 % loss, 3 seeded runs
# ArduPilot is left out by default: with it the run takes about 40 minutes, most of it in runs at
# 30 % loss, where an upload into ArduPilot waits on the vehicle's own 1 s re-request timer.
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"

if $quick; then
  settings=(--sizes 10,100 --losses 0,30 --flavours PX4 --success-runs 3 --floor-warmup 200 --floor-samples 500)
else
  settings=(--sizes 10,100,1000 --losses 0,10,30 --flavours PX4 --success-runs 20 --floor-warmup 500 --floor-samples 2000)
fi

machine_info

build_bench
# Stale default results go, unless options were given (they may name other files, next to these).
if [ $# -eq 0 ]; then rm -f "$results/mission.json" "$results/mission.md" "$results/mission-mavsdk-stderr.log"; fi

echo "== Python peers (MAVSDK 4.1)"
tools/python-peers.sh
echo "mavsdk $(.venv/bin/python -c 'import importlib.metadata as m; print(m.version("mavsdk"))')"

echo "== mission transfer"
# Every transfer is bounded inside the harness (120 s); this bounds the whole in case of a bug.
# Options given to this script come last, so they override these (a later option wins).
timeout 5400 java -Xms512m -Xmx512m -cp "$cp" pod.bench.mission.MissionBenchKt "${settings[@]}" \
  --python .venv/bin/python --mavsdk-script bench/mavsdk_mission.py \
  --mavsdk-log "$results/mission-mavsdk-stderr.log" \
  --json "$results/mission.json" --markdown "$results/mission.md" "$@" \
  || echo "mission harness exited with $?"
