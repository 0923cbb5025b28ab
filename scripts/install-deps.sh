#!/usr/bin/env bash
# Installs the Debian 12 packages ellvor needs; installs only what is missing,
# so it is cheap to run again. Needs root (or sudo) when something is missing.
# With arguments, installs those packages instead (`make fuzz` passes clang's).
set -euo pipefail
packages=(g++ make libflint-dev libflint-arb-dev libmpfr-dev libgmp-dev catch2 libeigen3-dev
          libcgal-dev nlohmann-json3-dev python3
          pybind11-dev python3-dev python3-numpy python3-matplotlib python3-pytest
          python3-distributed python3-dask python3-mpmath python3-scipy)
[ $# -eq 0 ] || packages=("$@")
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
