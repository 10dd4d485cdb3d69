#!/usr/bin/env bash
# Installs the dependencies (Debian 12, as root), builds, and runs the whole test suite.
#   bash tools/run_tests.sh [build-dir] [extra cmake arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift || true
bash tools/setup_debian.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
# Tests on explicitly: tools/run_demo.sh configures the same build/ with them off, and the
# cache would keep that choice. An empty test list is an error, not a pass.
cmake -S . -B "$build" -DLBDEM_TESTS=ON "$@"
cmake --build "$build" -j"$(nproc)"
cd "$build" && ctest --output-on-failure --no-tests=error -j"$(nproc)" --timeout 900
