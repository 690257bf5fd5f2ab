#!/usr/bin/env bash
# Builds the benchmarks and runs the engine-overhead harness (pod.bench.engine.EngineBenchKt): task
# trees of missions that finish at once, run as programs on one thread, so the time is the engine's
# own (task coroutines, events, vehicle claims):
#   concurrent  Concurrent(10,000 × Bound(Fly, one vehicle each))
#   sequence    Sequence(10,000 × Bound(Fly, the same vehicle))
#   deep        1,000 nested Sequence/Concurrent/Watch levels around one Fly
# three times: as is, with a collector on Engine.events, and with a fly that yields once.
# There is no peer to compare with. Results land in bench/target/results/engine.txt.
#
#   bench/engine.sh           the full run: 10 warm-up and 30 measured repetitions per case; about 1 minute on 2 cores
#   bench/engine.sh --quick   a smoke run with 2 + 3 repetitions (figures not meaningful)
# Any further option goes to the harness (a later option wins), e.g. --leaves 100000 or --cases deep --depth 10000.
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"

if $quick; then settings=(--warmup 2 --reps 3); else settings=(--warmup 10 --reps 30); fi

machine_info

build_bench

echo "== engine overhead"
# Other work on this machine shows in the figures: say how busy it was.
echo "load average before: $(load)"
{
  for variant in "" "--events true" "--yield true"; do
    # shellcheck disable=SC2086 # the variant is two words on purpose
    timeout 600 java -Xms1g -Xmx1g -cp "$cp" pod.bench.engine.EngineBenchKt "${settings[@]}" $variant "$@" \
      || echo "engine harness exited with $?"
    echo
  done
} | tee "$results/engine.txt"
echo "load average after: $(load)"
