#!/usr/bin/env bash
# Builds the benchmarks and runs issue 16's tlog benchmark (pod.bench.tlog.TlogBenchKt): writes a
# seeded synthetic tlog (4 copters streaming as ArduCopter does for 1 hour, and a ground station's
# heartbeat; MAVLink 2, Pod's TlogWriter) into bench/target/tlog/, then reads it with Pod's
# TlogTracks.read and TlogReader, with pymavlink (bench/pymavlink_tlog.py: mavutil + recv_msg), and
# replays it to a Pod GroundStation through a TlogReplayLink at 1000x and unpaced (--speed max: in log
# time, as pod replay wires it, so an hour of log replays in a fraction of a second). Every pass is
# checked against what was written. Prints the table; results land in bench/target/results/tlog.json
# and tlog.md (the Python peer's stderr in tlog-peers.log). About 2 minutes on 2 cores, 40 s after the build.
#
#   bench/tlog.sh             the full run
#   bench/tlog.sh --quick     a smoke run: 2 vehicles, 10 minutes of log, one pass each (seconds after the build)
#   any other option goes to the harness (a later option wins), e.g. --speeds 100,1000 --replays 5
# The Python with pymavlink is POD_PYTHON, else .venv/bin/python (tools/python-peers.sh makes it).
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"

if $quick; then
  settings=(--vehicles 2 --duration 10m --reads 1 --warmup 1 --python-reads 1 --python-warmup 0 --replays 1 --replay-warmup 0)
else
  settings=(--vehicles 4 --duration 1h --seed 1 --reads 5 --warmup 2 --python-reads 5 --python-warmup 1 --speeds 1000,max --replays 3 --replay-warmup 1)
fi

python="${POD_PYTHON:-$root/.venv/bin/python}"
if [ ! -x "$python" ]; then
  echo "no Python with pymavlink at $python: run tools/python-peers.sh or set POD_PYTHON" >&2
  exit 2
fi

machine_info
echo "Python $("$python" -c 'import platform; print(platform.python_version())'), pymavlink $("$python" -c 'import importlib.metadata as m; print(m.version("pymavlink"))'), fastcrc $("$python" -c 'import importlib.metadata as m; print(m.version("fastcrc"))' 2>/dev/null || echo none)"

build_bench

echo "== tlog read and replay"
# Other work on this machine shows in the figures: say how busy it was.
echo "load average before: $(load)"
# Every pass is bounded inside the harness; this bounds the whole in case of a bug.
status=0
timeout 1200 java -Xms512m -Xmx512m -cp "$cp" pod.bench.tlog.TlogBenchKt "${settings[@]}" \
  --log bench/target/tlog/synthetic.tlog --python "$python" --script bench/pymavlink_tlog.py \
  --peer-log "$results/tlog-peers.log" --json "$results/tlog.json" --markdown "$results/tlog.md" "$@" \
  || status=$?
echo "load average after: $(load)"
exit $status
