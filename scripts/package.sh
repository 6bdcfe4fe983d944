#!/usr/bin/env bash
# Builds monoplane's .deb for lab PCs (docs/install.md): a release build of the program and its
# simulated headset into build-package/ (or $BUILD_DIR), a man page per command (help2man from
# each --help), then CPack's DEB generator (cmake/packaging.cmake: dependencies by dpkg-shlibdeps
# plus the run-time ones), checked by desktop-file-validate and lintian. Prints the .deb's path
# last. Installs the Debian packages it needs (apt-get, as root or through sudo).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
# The build's packages, and the packaging tools.
scripts/install-deps.sh help2man desktop-file-utils lintian dpkg-dev file fakeroot

build=${BUILD_DIR:-build-package}
revision=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
project_version=$(sed -n 's/^project(monoplane VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
version="${project_version}+g${revision}"
echo "package: monoplane ${version} in ${build}/"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTING=OFF \
  -DCMAKE_INSTALL_PREFIX=/usr \
  -DMONOPLANE_PACKAGE_VERSION="$version" >/dev/null
cmake --build "$build" --target monoplane monoplane_simxr

# One man page per command, from its --help (gzip -n: the same bytes for the same page).
man="$build/man"
rm -rf "$man" && mkdir -p "$man"
page() {  # page NAME "SUMMARY" COMMAND...
  local name=$1 summary=$2
  shift 2
  # help2man names the page after the program it runs: a wrapper of that name.
  local wrapper="$build/man-bin/$name"
  mkdir -p "$build/man-bin"
  printf '#!/bin/sh\nexec %s "$@"\n' "$*" > "$wrapper"
  chmod +x "$wrapper"
  help2man --no-info --no-discard-stderr --version-string="$version" --name="$summary" \
    --output="$man/$name.1" "$wrapper"
  gzip -9n "$man/$name.1"
  rm "$wrapper"
}
exe="$root/$build/monoplane"
page monoplane "hybrid mono-stereo rendering and 2AFC perception studies for VR" "$exe"
"$exe" --help | sed -n '/^Subcommands:/,$p' | sed -n 's/^  \([a-z][a-z-]*\)  *\(.*\)$/\1\t\2/p' |
  while IFS=$'\t' read -r command summary; do
    page "monoplane-$command" "$(echo "$summary" | sed 's/ (docs\/[^)]*)//; s/;.*//')" "$exe $command"
  done

desktop-file-validate packaging/monoplane-lab.desktop
# The package's own changelog (a native package's, gzip -n) beside its copyright file.
doc="$build/package-doc"
rm -rf "$doc" && mkdir -p "$doc"
{
  echo "monoplane (${version}) unstable; urgency=low"
  echo
  echo "  * Built from commit ${revision}; the project's history is its git log."
  echo
  echo " -- monoplane developers <monoplane@example.org>  $(date -R -d @"$(git log -1 --format=%ct 2>/dev/null || date +%s)")"
} > "$doc/changelog"
gzip -9n "$doc/changelog"
cp packaging/copyright "$doc/copyright"

(cd "$build" && cpack -G DEB >/dev/null)
deb=$(ls -t "$build"/monoplane_*.deb | head -1)
echo "package: lintian ${deb}"
lintian --profile debian --suppress-tags-from-file packaging/lintian-accepted "$deb" || {
  echo "package: lintian reported findings that packaging/lintian-accepted does not list" >&2
  exit 1
}
echo "$deb"
