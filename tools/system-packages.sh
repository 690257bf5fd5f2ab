#!/usr/bin/env bash
# Installs the Debian packages the tests drive and the build cannot fetch itself: socat makes the
# pseudo-terminal pairs that stand in for a serial telemetry radio in the serial-link tests;
# chromium and its chromedriver are the real browser the `pod gcs` page is tested in.
# Does nothing when every one is already installed; needs root (apt-get), as on CI.
set -euo pipefail
# package:command it provides
packages=(socat:socat chromium:chromium chromium-driver:chromedriver)
missing=()
for p in "${packages[@]}"; do
  command -v "${p#*:}" >/dev/null 2>&1 || missing+=("${p%%:*}")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "system-packages: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq "${missing[@]}" >/dev/null
