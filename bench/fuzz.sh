#!/usr/bin/env bash
# Builds the benchmarks and runs issue 27's decoder soak (pod.bench.fuzz.FuzzSoakKt): every decoder
# (UDP datagrams, byte streams as TCP and serial links feed them, signed frames through signature
# check and replay guard, tlogs) under 10 million seeded mutated inputs each, from the harness CI
# runs at 100k (mavlink's pod.mavlink.fuzz, shipped to this module as pod-mavlink's test jar).
# Prints per decoder the time, inputs/s, escapes, violated properties and hangs (zero expected;
# exit status 1 otherwise); results land in bench/target/results/fuzz.json and fuzz.md.
# Runs niced: the machine is shared.
#
#   bench/fuzz.sh            the full run: 10 million inputs per decoder, 2 decoders at a time
#   bench/fuzz.sh --quick    a smoke run: 100k inputs per decoder
#   any other option goes to the harness (a later option wins), e.g. --decoders tlog --threads 1
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"

if $quick; then
  settings=(--inputs 100000)
else
  settings=(--inputs 10000000)
fi

machine_info
build_bench

echo "== decoder soak"
echo "load average before: $(load)"
status=0
# Every run stops by itself (its inputs done, or its first stuck input); this bounds the whole.
timeout 14400 nice -n 10 java -Xms512m -Xmx512m -cp "$cp" pod.bench.fuzz.FuzzSoakKt "${settings[@]}" \
  --json "$results/fuzz.json" --markdown "$results/fuzz.md" "$@" || status=$?
echo "load average after: $(load)"
exit $status
