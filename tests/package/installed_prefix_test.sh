#!/usr/bin/env bash
# installed_prefix_test.sh BUILD_DIR SOURCE_DIR
#
# monoplane runs the same from an installed prefix as from its build folder (docs/install.md):
# `cmake --install` into a temporary prefix, the build folder moved out of the way of nothing,
# then from the prefix: --version, the shipped protocols found by `protocol check`, and a short
# session of the demo protocol on the simulated headset (the runtime and its manifest found beside
# the executable). No path of the source or build folder is in the installed binaries (`strings`).
set -euo pipefail
build=$(realpath "${1:?build folder}")
source=$(realpath "${2:?source folder}")
prefix=$(mktemp -d "${TMPDIR:-/tmp}/monoplane-prefix.XXXXXX")
trap 'rm -rf "$prefix"' EXIT
fail() { echo "installed_prefix_test: FAILED: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >/dev/null
# The runtime's folder: lib/<multiarch>/monoplane on Debian, lib/monoplane elsewhere.
plugin=$(cd "$prefix" && ls lib/*/monoplane/libmonoplane_simxr.so lib/monoplane/libmonoplane_simxr.so \
  2>/dev/null | head -1 || true)
[ -n "$plugin" ] || fail "the simulated runtime's library was not installed"
for f in bin/monoplane share/monoplane/simxr/simxr.json \
         share/monoplane/protocols/demo.toml share/applications/monoplane-lab.desktop \
         share/icons/hicolor/scalable/apps/monoplane.svg share/doc/monoplane/docs/install.md; do
  [ -e "$prefix/$f" ] || fail "$f was not installed"
done
for binary in bin/monoplane "$plugin"; do
  for folder in "$source" "$build"; do
    if strings "$prefix/$binary" | grep -qF "$folder"; then
      fail "$binary holds the path $folder: $(strings "$prefix/$binary" | grep -F "$folder" | head -3)"
    fi
  done
done

exe="$prefix/bin/monoplane"
"$exe" --version | grep -q '^study database schema: ' || fail "--version"
# The protocols folder of the installation, not the source tree's.
"$exe" protocol check "$prefix/share/monoplane/protocols/demo.toml" >/dev/null ||
  fail "protocol check of the installed demo protocol"
work="$prefix/work"
mkdir -p "$work"
# One trial, no practice, few frames (a fixed seed, 5 frames per simulated second): what is tested
# is that the installed files are found, not the session (about 6 s alone, rather than 15 to 65 s
# with practice trials and the observer's viewing times left to chance).
cat > "$work/short.toml" <<'TOML'
name = "short"
scenes = ["beams"]
mono_planes = [8]
alternatives = ["stereo", "hybrid"]
practice_trials = 0
TOML
(cd "$work" && env -u XR_RUNTIME_JSON "$exe" study run --protocol short.toml --participant P01 \
  --db study.sqlite --headset simulated --observer default --hmd vive --resolution-scale 0.1 \
  --sim-rate 5 --neutral-s 0.3 --seed 1 --detail test --window off) > "$work/run.log" 2>&1 ||
  fail "the session from the installed prefix: $(tail -5 "$work/run.log")"
"$exe" study list --db "$work/study.sqlite" | grep -q P01 || fail "study list"
"$exe" study export --db "$work/study.sqlite" --format csv --out "$work/study.csv" >/dev/null
head -1 "$work/study.csv" | grep -q ',software_version' || fail "the export has no software_version"
echo "installed_prefix_test: passed ($prefix)"
