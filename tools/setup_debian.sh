#!/usr/bin/env bash
# Installs every build and run dependency from Debian 12's packages (run as root).
# --with-paraview also installs what the study's pictures need (pvbatch under a virtual X
# display: paraview, python3-paraview, xvfb, xauth; about 0.8 GB).
# Usage: setup_debian.sh [--with-paraview]
set -euo pipefail
paraview=()
for arg in "$@"; do
  case $arg in
    --with-paraview) paraview=(paraview python3-paraview xvfb xauth) ;;
    *) echo "setup_debian.sh: unknown option '$arg' (usage: setup_debian.sh [--with-paraview])" >&2
       exit 2 ;;
  esac
done
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends \
  build-essential cmake git googletest libgtest-dev \
  libopenmpi-dev openmpi-bin liblammps-dev lammps \
  libeigen3-dev libhdf5-openmpi-dev libyaml-cpp-dev libspdlog-dev \
  python3 python3-numpy python3-h5py python3-matplotlib python3-yaml python3-jsonschema \
  "${paraview[@]}"
