#!/usr/bin/env bash
# Issue 30, target 5: how fast the `pod` command starts, beside the Python peers in the same run.
# Times whole processes, round-robin (each round runs every case once, so a change in the machine's
# load falls on all of them alike), and prints the median (min–max) wall time and the median CPU
# time (user + system, children included) of each:
#   pod --help, pod --version                    ./pod as it ships (class-data-sharing archive)
#   pod --help, before issue 30                  java as ./pod ran it before: no archive, JNA unpacked each start
#   mavproxy.py --version                        MAVProxy's start (the peer of --help)
#   python -c "from pymavlink import mavutil"    pymavlink's import
#   pod arm --sysid 1 (now and before)           against `pod sim --time-scale 10` on loopback
#   pymavlink arm (bench/pymavlink_arm.py)       the same exchange; it reports the vehicle's answer time
# A command's overhead is its wall time minus the vehicle's answer time, which pymavlink's script
# measures inside itself (socket open to armed: at --time-scale 10 a heartbeat comes every 100 ms;
# at 40 the copter disarmed itself after 0.25 s, before a loaded machine saw it armed).
#
#   bench/start.sh            11 rounds
#   bench/start.sh --quick    3 rounds
#   RUNS=N bench/start.sh     N rounds; POD_START_PORT picks the loopback port (default 14655)
# Not preamble.sh: this needs no benchmark jar (./pod builds what it times).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
load() { cut -d' ' -f1-3 /proc/loadavg; }
runs="${RUNS:-11}"
[ "${1:-}" = "--quick" ] && runs=3
port="${POD_START_PORT:-14655}"
python="${POD_PYTHON:-$root/.venv/bin/python}"
mavproxy="$(dirname "$python")/mavproxy.py"
for tool in "$python" "$mavproxy"; do
  [ -x "$tool" ] || { echo "no $tool: run tools/python-peers.sh or set POD_PYTHON" >&2; exit 2; }
done

echo "== machine"
echo "cores: $(nproc); CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'); JDK: $(java -version 2>&1 | head -2 | tail -1)"
echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo '?')$(git diff --quiet 2>/dev/null || echo ' (with uncommitted changes)')"
echo "Python $("$python" -c 'import platform; print(platform.python_version())'), pymavlink $("$python" -c 'import importlib.metadata as m; print(m.version("pymavlink"))'), MAVProxy $("$python" -c 'import importlib.metadata as m; print(m.version("MAVProxy"))')"

echo "== build (./pod builds the command and its start archive if they are not current)"
./pod --version >/dev/null
before=(java -XX:+UseSerialGC -XX:TieredStopAtLevel=1 -cp "cli/target/pod-cli.jar:cli/target/lib/*" pod.cli.MainKt)

work="$(mktemp -d)"
sim_pid=
cleanup() { [ -n "$sim_pid" ] && kill "$sim_pid" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
./pod sim --time-scale 10 --out "udpout:127.0.0.1:$port" >"$work/sim.log" 2>&1 &
sim_pid=$!
arm=(arm --sysid 1 --connect "udpin:127.0.0.1:$port")

# case name → command (an array per case, by name)
names=(pod-help pod-version before-help mavproxy-version pymavlink-import pod-arm before-arm pymavlink-arm)
declare -A label=(
  [pod-help]="pod --help" [pod-version]="pod --version" [before-help]="pod --help, before (no archive)"
  [mavproxy-version]="mavproxy.py --version" [pymavlink-import]="python -c \"from pymavlink import mavutil\""
  [pod-arm]="pod arm --sysid 1" [before-arm]="pod arm --sysid 1, before (no archive)" [pymavlink-arm]="pymavlink arm (bench/pymavlink_arm.py)"
)
run_case() {
  case "$1" in
    pod-help) ./pod --help ;;
    pod-version) ./pod --version ;;
    before-help) "${before[@]}" --help ;;
    mavproxy-version) "$mavproxy" --version ;;
    pymavlink-import) "$python" -c "from pymavlink import mavutil" ;;
    pod-arm) ./pod "${arm[@]}" ;;
    before-arm) "${before[@]}" "${arm[@]}" ;;
    pymavlink-arm) "$python" bench/pymavlink_arm.py "$port" ;;
  esac
}

# One timed run: "wall user sys exit" appended to $work/<case>.times, its stdout kept for the answer time.
timed() {
  local name=$1 status=0
  TIMEFORMAT='%R %U %S'
  { time run_case "$name" >"$work/$name.out" 2>"$work/$name.err" || status=$?; } 2>"$work/t"
  echo "$(tail -1 "$work/t") $status" >>"$work/$name.times"
  [ "$name" = pymavlink-arm ] && [ "$status" = 0 ] && "$python" -c 'import json,sys; print(json.loads(sys.stdin.read())["answer_s"])' <"$work/$name.out" >>"$work/answers"
  return 0
}

echo "== $runs rounds (load average before: $(load))"
# The simulated copter is up and accepts arming: freshly booted, it refuses (MAV_RESULT_FAILED) until
# its pre-arm checks pass, as ArduCopter does, so ask again, a bounded number of times.
for attempt in $(seq 60); do
  "$python" bench/pymavlink_arm.py "$port" >/dev/null 2>&1 && break
  [ "$attempt" = 60 ] && { echo "the simulated copter did not accept arming in 60 attempts: $(tail -3 "$work/sim.log")" >&2; exit 1; }
done
for round in $(seq "$runs"); do
  for name in "${names[@]}"; do timed "$name"; done
done
echo "load average after: $(load)"

median() { sort -n | awk '{a[NR]=$1} END {if (NR) printf "%.3f", (NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
range() { sort -n | awk 'NR==1 {lo=$1} {hi=$1} END {printf "%.3f–%.3f", lo, hi}'; }
echo
echo "| command | runs (failed) | wall, s: median (min–max) | CPU, s: median |"
echo "|---|---:|---:|---:|"
for name in "${names[@]}"; do
  f="$work/$name.times"
  failed=$(awk '$4 != 0' "$f" | wc -l)
  echo "| ${label[$name]} | $runs ($failed) | $(awk '{print $1}' "$f" | median) ($(awk '{print $1}' "$f" | range)) | $(awk '{print $2 + $3}' "$f" | median) |"
done
answer=$(median <"$work/answers")
echo
echo "vehicle's answer (pymavlink, socket open to armed): median $answer s"
for name in pod-arm before-arm pymavlink-arm; do
  echo "overhead of ${label[$name]}: $(awk '{print $1}' "$work/$name.times" | median | awk -v a="$answer" '{printf "%.3f", $1 - a}') s (median wall − answer)"
done
if grep -qv ' 0$' "$work"/*.times; then
  echo "some runs failed; the last error of each:" >&2
  for name in "${names[@]}"; do [ -s "$work/$name.err" ] && echo "  $name: $(tail -1 "$work/$name.err")" >&2; done
  exit 1
fi
