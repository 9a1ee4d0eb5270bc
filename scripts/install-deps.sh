#!/usr/bin/env bash
# Installs the Debian packages the build and tests need, but only those missing.
# Quiet and fast (a dpkg query) when everything is already present.
# Usage: install-deps.sh [PACKAGE...]: also the packages named (a test's own
# tools, e.g. lintian for the .deb's check, which the build does not need).
set -euo pipefail
PKGS=(
  build-essential cmake pkg-config ccache
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libfmt-dev
  libcurl4-openssl-dev libcpp-httplib-dev
  wordnet-dev wordnet-base
  libcairo2-dev libpng-dev libgif-dev
  chromium python3-websocket
  clang-14 libclang-rt-14-dev libfuzzer-14-dev
  pybind11-dev python3-dev python3-pytest
  python3-venv python3-pip python3-setuptools python3-wheel
  clips libclips-dev
  python3-matplotlib python3-nbconvert python3-ipykernel
  python3-jsonschema
  "$@"
)
missing=()
for p in "${PKGS[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >/dev/null || { echo "install-deps: apt-get update failed" >&2; exit 1; }
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null \
  || { echo "install-deps: apt-get install failed for: ${missing[*]}" >&2; exit 1; }
