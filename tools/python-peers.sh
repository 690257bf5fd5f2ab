#!/usr/bin/env bash
# Creates .venv at the repository root with the Python reference peers that the interop tests
# drive (pymavlink, mavsdk). Does nothing when .venv already holds exactly these requirements.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
req="$root/src/test/python/requirements.txt"
stamp="$root/.venv/.pod-requirements"
if [ -x "$root/.venv/bin/python" ] && cmp -s "$req" "$stamp"; then
  exit 0
fi
echo "python-peers: creating $root/.venv with $(grep -v '^#' "$req" | tr '\n' ' ')"
python3 -m venv "$root/.venv"
"$root/.venv/bin/pip" install -q --disable-pip-version-check -r "$req"
cp "$req" "$stamp"
