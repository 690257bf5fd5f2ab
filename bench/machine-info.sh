#!/usr/bin/env bash
# Prints the "== machine" block the benchmark scripts start with: cores, CPU, memory, JDK, OS and
# the commit measured (marked when the tree has uncommitted changes). Run from the repository root.
echo "== machine"
echo "cores: $(nproc); CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'); memory: $(free -g | awk '/^Mem:/ {print $2 " GiB"}')"
echo "JDK: $(java -version 2>&1 | head -2 | tail -1)"
echo "OS: $(. /etc/os-release 2>/dev/null && echo "$PRETTY_NAME"), kernel $(uname -r)"
echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo '?')$(git diff --quiet 2>/dev/null || echo ' (with uncommitted changes)')"
