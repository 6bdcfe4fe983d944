#!/usr/bin/env bash
# Builds the non-GPU unit tests with AddressSanitizer and UndefinedBehaviorSanitizer, without
# Vulkan at all, into build-sanitize/ (scripts/test-sanitizers.sh runs them). Extra arguments go to
# cmake --build.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=build-sanitize CMAKE_ARGS="-DMONOPLANE_VULKAN=OFF -DMONOPLANE_SANITIZE=ON" \
  scripts/build.sh "$@"
