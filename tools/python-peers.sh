#!/usr/bin/env bash
# Creates .venv at the repository root with the Python reference peers that the interop tests
# drive (pymavlink, mavsdk, MAVProxy). Does nothing when .venv already holds exactly these
# requirements.
#
# MAVProxy goes in without its declared dependencies: they pull in opencv, vtk and matplotlib
# (hundreds of MB) for its map and graph modules, which the tests never load. What it needs to
# route and log (pymavlink, pyserial) is in requirements.txt.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
req="$root/src/test/python/requirements.txt"
nodeps="$root/src/test/python/requirements-nodeps.txt"
stamp="$root/.venv/.pod-requirements"
if [ -x "$root/.venv/bin/python" ] && cat "$req" "$nodeps" | cmp -s - "$stamp"; then
  exit 0
fi
echo "python-peers: creating $root/.venv with $(cat "$req" "$nodeps" | grep -v '^#' | tr '\n' ' ')"
python3 -m venv "$root/.venv"
"$root/.venv/bin/pip" install -q --disable-pip-version-check -r "$req"
"$root/.venv/bin/pip" install -q --disable-pip-version-check --no-deps -r "$nodeps"
cat "$req" "$nodeps" > "$stamp"
