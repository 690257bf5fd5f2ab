#!/usr/bin/env bash
# The ground station at fleet scale: 250 simulated copters (`pod sim`, real time, in a JVM of their
# own) flying outwards with GLOBAL_POSITION_INT at 10 Hz, the `pod gcs` server in the harness's JVM,
# and the page in headless chromium (Debian's chromium and chromedriver). Measures the server's CPU
# with no page and with the page open, the WebSocket's messages, bytes and batches, and in the
# browser the frame time (requestAnimationFrame), long tasks and heap. The page's screenshot goes to
# bench/target/results/gcs-250.png.
#
#   bench/gcs.sh                 windows of 60 s (the BENCHMARKS.md figure)
#   bench/gcs.sh --quick         windows of 10 s (figures not meaningful)
#   bench/gcs.sh --vehicles 50   any other option goes to pod.bench.gcs.GcsBenchKt
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"

if $quick; then settings=(--window 10s); else settings=(--window 60s); fi

machine_info
echo "chromium: $(chromium --version 2>/dev/null || echo '?')"
build_bench
echo "== gcs"
echo "load average before: $(load)"
timeout 1200 java -Xms512m -Xmx1g -cp "$cp" pod.bench.gcs.GcsBenchKt "${settings[@]}" \
  --json "$results/gcs.json" "$@" | tee "$results/gcs.md"
echo "load average after: $(load)"
