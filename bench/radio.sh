#!/usr/bin/env bash
# Builds the benchmarks and runs the radio upload harness (pod.bench.radio.RadioUploadBenchKt): a
# 200-item mission upload into a simulated ArduCopter behind an emulated 57600-baud SiK radio pair
# on loopback UDP, by Pod, pymavlink (bench/pymavlink_radio_upload.py) and MAVProxy (`wp load`),
# 5 runs each (median), against the link's own limit (bytes carried ÷ 5760 bytes/s).
#
#   bench/radio.sh            about 2 minutes on 2 cores
#   bench/radio.sh --quick    one run each
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"
runs=5
if $quick; then runs=1; fi
machine_info
build_bench
tools/python-peers.sh >/dev/null
wpl="$results/radio-200.txt"
.venv/bin/python - "$wpl" <<'PY'
import sys
lines = ["QGC WPL 110"]
for i in range(200):
    lines.append("\t".join(map(str, [i, 1 if i == 0 else 0, 0 if i == 0 else 3, 16, 0, 0, 0, 0,
                                     "%.7f" % (41.1780460 + 0.0001 * i), "-8.5957860", 30 if i else 120, 1])))
open(sys.argv[1], "w").write("\n".join(lines) + "\n")
PY
echo "load before: $(load)"
timeout 1200 java -Xms256m -Xmx512m -cp "$cp" pod.bench.radio.RadioUploadBenchKt .venv/bin/python .venv/bin/mavproxy.py "$wpl" "$runs" \
  | tee "$results/radio.md" || echo "radio harness exited with $?"
echo "load after: $(load)"
