#!/usr/bin/env bash
# Installs every build and run dependency from Debian 12's packages (run as root).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends \
  build-essential cmake git googletest libgtest-dev \
  libopenmpi-dev openmpi-bin liblammps-dev lammps \
  libeigen3-dev libhdf5-openmpi-dev libyaml-cpp-dev libspdlog-dev \
  python3 python3-numpy python3-h5py python3-matplotlib python3-yaml
