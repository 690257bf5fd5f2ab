#!/usr/bin/env bash
# Builds the benchmarks and runs issue 15's waypoint-action benchmark (pod.bench.waypoints.WaypointBenchKt):
# what stopping at each waypoint to run an action costs, in the vehicle's own time, for each way
# of making a copter stop and hold there — (a) the mission queue's stop-and-go (WaypointFlight),
# (b) an AUTO mission with a switch to the hold mode on MISSION_ITEM_REACHED, (c) an AUTO mission
# whose waypoints hold long and MISSION_SET_CURRENT to move on — beside the same path flown
# without stops, on a simulated ArduCopter and PX4 copter, over real UDP sockets on 127.0.0.1,
# straight and through a relay with 50 ms delay each way, the simulator in real time.
# Results land in bench/target/results/waypoints.json and waypoints.md.
#
#   bench/waypoints.sh           the full run: 8 waypoints 40 m apart at 30 m, a 2 s action at each,
#                                both autopilots, loopback and 100 ms RTT; ~30 minutes
#   bench/waypoints.sh --quick   a smoke run: 3 waypoints, ArduCopter, loopback; ~2 minutes
#   any other option goes to the harness (a later option wins), e.g. --reps 2
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"

if $quick; then
  settings=(--autopilots ARDUPILOT --conditions LOOPBACK --waypoints 3)
else
  settings=(--autopilots ARDUPILOT,PX4 --conditions LOOPBACK,RTT100 --waypoints 8 --spacing 40 --height 30 --action 2s)
fi

machine_info

build_bench

echo "== waypoint action overhead"
# Every flight is bounded inside the harness (10 minutes); this bounds the whole in case of a bug.
timeout 5400 java -Xms512m -Xmx512m -cp "$cp" pod.bench.waypoints.WaypointBenchKt "${settings[@]}" \
  --json "$results/waypoints.json" --markdown "$results/waypoints.md" "$@" \
  || echo "waypoint harness exited with $?"
