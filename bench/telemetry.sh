#!/usr/bin/env bash
# Datagram → telemetry StateFlow for the five hot telemetry messages (issue 30, target 3): JMH's
# TelemetryPathBenchmark with -prof gc (gc.alloc.rate.norm = bytes allocated per datagram, ns/op),
# on each built worktree given, back to back, with the load average beside each run.
#
#   bench/telemetry.sh [--quick] DIR...     e.g. bench/telemetry.sh /work/wt-before-telemetry /work/main
#
# Each DIR needs a bench jar holding the benchmark (built with `./mvnw -B -ntp -Pbench -pl bench
# -am package -DskipTests`). A tree from before issue 30 lacks it: copy
# bench/src/main/kotlin/pod/bench/TelemetryPathBenchmarks.kt in and change `telemetry.hud` to
# `telemetry.linkQuality` (VFR_HUD had no telemetry value then), then build it.
# BENCH_SELECT picks other methods or parameters (default: feed, changing and unchanged values).
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"
set +e +o pipefail
if $quick; then jmh_settings=(-f 1 -wi 2 -w 1s -i 3 -r 1s); else jmh_settings=(-f 2 -wi 3 -w 2s -i 5 -r 2s); fi
select="${BENCH_SELECT:-TelemetryPathBenchmark.feed$}"
out="$root/bench/target/results/telemetry"; mkdir -p "$out"
machine_info
for dir in "$@"; do
  side=$(basename "$dir")
  echo "== telemetry path on $side ($(cd "$dir" && git rev-parse --short HEAD 2>/dev/null)); load average before: $(load)"
  timeout 1200 java -cp "$(bench_jar "$dir"):$dir/bench/target/lib/*" org.openjdk.jmh.Main "${jmh_settings[@]}" \
    -jvmArgs "-Xms512m -Xmx512m" -prof gc -rf json -rff "$out/jmh-$side.json" "$select" \
    | grep -E '^(Benchmark|TelemetryPathBenchmark\.[a-zA-Z]+ |TelemetryPathBenchmark.*alloc\.rate\.norm)'
  echo "load average after: $(load)"
done
