# The start every benchmark script shares; sourced, not run: `. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"`.
# Strict mode, the repository root as working directory, where the jar and the results are, the
# --quick flag, and the steps each script begins with, so that a change to them is made once.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
results="$root/bench/target/results"
# The benchmark jar of a worktree, whatever version it was built at (pod-bench-<version>.jar).
bench_jar() { ls "$1"/bench/target/pod-bench-*.jar 2>/dev/null | grep -v -- '-sources' | head -1; }
cp="$(bench_jar "$root"):$root/bench/target/lib/*"

# `--quick` first: a smoke run with short settings (figures not meaningful); taken off the arguments
# the script passes on to its harness.
quick=false
if [ "${1:-}" = "--quick" ]; then quick=true; shift; fi

# The "== machine" block: cores, CPU, memory, JDK, OS, the socket receive buffer limit, and the
# commit measured (marked when the tree has uncommitted changes).
machine_info() {
  echo "== machine"
  echo "cores: $(nproc); CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'); memory: $(free -g | awk '/^Mem:/ {print $2 " GiB"}')"
  echo "JDK: $(java -version 2>&1 | head -2 | tail -1)"
  echo "OS: $(. /etc/os-release 2>/dev/null && echo "$PRETTY_NAME"), kernel $(uname -r); net.core.rmem_max $(cat /proc/sys/net/core/rmem_max 2>/dev/null || echo '?')"
  echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo '?')$(git diff --quiet 2>/dev/null || echo ' (with uncommitted changes)')"
}

# Builds the benchmark jar and the libraries beside it (SKIP_BUILD=1: use the ones built), then
# makes the results folder.
build_bench() {
  if [ "${SKIP_BUILD:-}" != "1" ]; then
    echo "== build"
    ./mvnw -B -ntp -Dkotlin.compiler.daemon=false -Pbench -pl bench -am package -DskipTests
  fi
  mkdir -p "$results"
  cp="$(bench_jar "$root"):$root/bench/target/lib/*"
}

# The load average now: other work on this machine shows in the figures, so each run says how busy it was.
load() { cut -d' ' -f1-3 /proc/loadavg; }
