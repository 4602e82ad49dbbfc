#!/usr/bin/env bash
# Install what moorsph needs on Debian 12, skipping what is already there.
# Run as root (or with sudo available). Idempotent.
set -euo pipefail
packages=(build-essential cmake pkg-config libeigen3-dev libsimbody-dev libhdf5-dev libyaml-cpp-dev
          libcli11-dev libgtest-dev python3-h5py python3-numpy python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "moorsph: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
