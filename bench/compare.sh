#!/usr/bin/env bash
# Paired before/after runs of the receive-path targets (issue 13), on two built worktrees, back to
# back, same settings, the load average beside each: ingest (20,000/s and flood, Pod beside a bare
# NIO receiver), command round trip (Pod beside pymavlink; 1, 10, 100 vehicles and 30 % loss),
# 1000-item upload without loss (Pod beside MAVSDK, PX4 and ArduPilot vehicles).
# Each worktree must have been built with `./mvnw -B -ntp -Pbench -pl bench -am package -DskipTests`
# and the Python peers installed in this one (tools/python-peers.sh).
#
#   bench/compare.sh /work/wt-before /work/wt-recv [ingest|command|mission ...]
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"
# Every part runs even when one fails: a comparison with a hole in it still says something.
set +e +o pipefail
before=$1; after=$2; shift 2
parts=("${@:-ingest command mission}"); parts=(${parts[@]})
out="$root/bench/target/results/compare"; mkdir -p "$out"
py="$root/.venv/bin/python"
machine_info
for part in "${parts[@]}"; do
  for dir in "$before" "$after"; do
    side=$(basename "$dir")
    cp="$(bench_jar "$dir"):$dir/bench/target/lib/*"
    echo "== $part on $side ($(cd "$dir" && git rev-parse --short HEAD)); load average before: $(load)"
    case $part in
      ingest) timeout 600 java -Xms512m -Xmx512m -cp "$cp" pod.bench.IngestBenchKt --count 200000 --repeats 3 \
          --rates 20000,max --json "$out/ingest-$side.json" ;;
      command) timeout 1200 java -Xms512m -Xmx512m -cp "$cp" pod.bench.command.CommandBenchKt --counts 1,10,100 \
          --rounds 200,50,20 --warmup 20,5,3 --lossy-rounds 30 --lossy-warmup 3 --pod-warmup 200 \
          --python "$py" --script "$dir/bench/pymavlink_command.py" --peer-log "$out/command-peers-$side.log" \
          --json "$out/command-$side.json" --markdown "$out/command-$side.md" ;;
      mission) timeout 1200 java -Xms512m -Xmx512m -cp "$cp" pod.bench.mission.MissionBenchKt --sizes 1000,1000,1000 --losses 0 \
          --flavours PX4,ARDUPILOT --success-runs 0 --floor-warmup 100 --floor-samples 200 \
          --python "$py" --mavsdk-script "$dir/bench/mavsdk_mission.py" --mavsdk-log "$out/mission-mavsdk-$side.log" \
          --json "$out/mission-$side.json" --markdown "$out/mission-$side.md" ;;
    esac
    echo "load average after: $(load)"
  done
done
