#!/usr/bin/env bash
# Configures and builds monoplane into build/ (or $BUILD_DIR). Extra arguments go to cmake --build.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${BUILD_DIR:-build}"
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build_dir" "$@"
