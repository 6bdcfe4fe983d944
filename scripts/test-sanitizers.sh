#!/usr/bin/env bash
# The non-GPU unit tests built with AddressSanitizer and UndefinedBehaviorSanitizer, without
# Vulkan at all: this build also proves that rig, scenes, hmd, study and analysis need no Vulkan.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build-sanitizers.sh
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0" \
  ctest --test-dir build-sanitize --output-on-failure -j "$(nproc)" -L unit
