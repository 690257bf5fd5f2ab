#!/usr/bin/env bash
# Prints the "== machine" block the benchmark scripts start with (see machine_info in preamble.sh).
# Run from anywhere.
. "$(dirname "${BASH_SOURCE[0]}")/preamble.sh"
machine_info
