#!/usr/bin/env bash
# Install, from Debian 12 packages, everything indent needs to build, test and plot.
# Idempotent: when every package is present it returns after one dpkg query.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git time
  petsc-dev libhdf5-openmpi-dev openmpi-bin libopenmpi-dev libmetis-dev
  libopenblas0-serial gmsh
  python3 python3-numpy python3-scipy python3-h5py python3-matplotlib python3-meshio python3-xlrd
  slurm-wlm munge
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
