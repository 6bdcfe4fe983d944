#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, and runs every test (unit tests,
# GPU tests on llvmpipe when there is no GPU, with Vulkan validation layers on).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
ctest --test-dir "${BUILD_DIR:-build}" --output-on-failure -j "$(nproc)"
