#!/usr/bin/env bash
# fresh_lab_pc.sh DEB
# fresh_lab_pc.sh --from-ctest SOURCE_DIR   (ctest: builds the .deb with scripts/package.sh first,
#                                           when MONOPLANE_PACKAGE_TEST=1; else skips)
#
# The .deb on a new lab PC: a fresh Debian 12 root (debootstrap, from the package source apt uses
# on this machine), the package installed there with apt so that its dependencies resolve, and
# inside that root, with no source tree: `monoplane --version`, the demo protocol on the simulated
# headset to completion, `study export` and `analyze`. Then the same over an upgrade: an earlier
# version of the package (this one, relabelled 0.0.1) is installed, a study database made with
# it, the package upgraded and the database read again, and removing the package leaves it.
#
# Needs root (debootstrap, chroot, mounts) and the network to the package source. Exit status 0
# when every check passed, 77 (ctest's skip) when this machine cannot run it, 1 otherwise.
# The root is kept in $MONOPLANE_FRESH_ROOT (default /var/tmp/monoplane-fresh-root) between runs:
# a later run only refreshes it (apt-get update) and removes what an earlier run installed.
set -euo pipefail

skip() { echo "fresh_lab_pc: SKIPPED: $*"; exit 77; }

if [ "${1:-}" = "--from-ctest" ]; then
  [ "${MONOPLANE_PACKAGE_TEST:-}" = 1 ] ||
    skip "set MONOPLANE_PACKAGE_TEST=1 to build the .deb and install it in a fresh Debian 12 root (root, network, several minutes; docs/install.md)"
  deb=$(bash "${2:?the source folder}/scripts/package.sh" | tail -1)
else
  deb=${1:?usage: fresh_lab_pc.sh DEB}
fi
deb=$(realpath "$deb")
root=${MONOPLANE_FRESH_ROOT:-/var/tmp/monoplane-fresh-root}
[ "$(id -u)" -eq 0 ] || skip "needs root (debootstrap, chroot)"
command -v debootstrap >/dev/null || skip "debootstrap is not installed (apt-get install debootstrap)"
command -v dpkg-deb >/dev/null || skip "dpkg-deb is missing"

# The mirror apt uses here (deb822 sources, else sources.list).
mirror=$(sed -n 's/^URIs: *\([^ ]*debian\/*\)$/\1/p' /etc/apt/sources.list.d/*.sources 2>/dev/null |
  grep -v security | head -1 || true)
[ -n "$mirror" ] || mirror=$(awk '$1 == "deb" && $2 !~ /security/ {print $2; exit}' \
  /etc/apt/sources.list 2>/dev/null || true)
[ -n "$mirror" ] || mirror=http://deb.debian.org/debian

mounted=()
cleanup() {
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[$i]}" 2>/dev/null || true; done
}
trap cleanup EXIT

if [ ! -x "$root/usr/bin/apt-get" ]; then
  echo "fresh_lab_pc: debootstrap bookworm from $mirror into $root"
  rm -rf "$root"
  debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
    skip "debootstrap failed (no network to $mirror?): $(tail -3 "$root.debootstrap.log")"
fi
for m in proc sys dev dev/pts; do
  mount --bind "/$m" "$root/$m"
  mounted+=("$root/$m")
done
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
in_root() { chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin \
  DEBIAN_FRONTEND=noninteractive LANG=C.UTF-8 "$@"; }
in_root apt-get update -qq
in_root apt-get purge -y -qq monoplane >/dev/null 2>&1 || true
rm -rf "$root/root/lab"

# No source tree in the root: the program must find everything in its own prefix.
fail() { echo "fresh_lab_pc: FAILED: $*" >&2; exit 1; }

# The earlier version: this package relabelled, to upgrade from.
work=$(mktemp -d)
dpkg-deb -R "$deb" "$work/earlier"
sed -i 's/^Version: .*/Version: 0.0.1/' "$work/earlier/DEBIAN/control"
dpkg-deb -b --root-owner-group "$work/earlier" "$root/tmp/monoplane-earlier.deb" >/dev/null
cp "$deb" "$root/tmp/monoplane-new.deb"
rm -rf "$work"

echo "fresh_lab_pc: apt install the earlier package and its dependencies"
in_root apt-get install -y -qq /tmp/monoplane-earlier.deb >/dev/null || fail "apt could not install the package"
in_root monoplane --version | tee "$root/tmp/version-earlier.txt"
grep -q "^study database schema: " "$root/tmp/version-earlier.txt" || fail "--version lacks the schema"

echo "fresh_lab_pc: the demo protocol on the simulated headset, with the earlier package"
mkdir -p "$root/root/lab"
in_root sh -c 'cd /root/lab && monoplane study run --protocol /usr/share/monoplane/protocols/demo.toml \
  --participant P01 --db /root/lab/study.sqlite --headset simulated --observer default \
  --hmd vive --resolution-scale 0.2 --sim-rate 15 --detail low --window off' ||
  fail "the demo session did not complete"

echo "fresh_lab_pc: upgrade to the new package; the database stays"
before=$(sha256sum "$root/root/lab/study.sqlite" | cut -d' ' -f1)
in_root apt-get install -y -qq /tmp/monoplane-new.deb >/dev/null || fail "the upgrade failed"
in_root monoplane --version | grep -q "^monoplane " || fail "--version after the upgrade"
[ "$(sha256sum "$root/root/lab/study.sqlite" | cut -d' ' -f1)" = "$before" ] ||
  fail "the upgrade changed the study database"
in_root monoplane study list --db /root/lab/study.sqlite | tee "$root/tmp/list.txt"
grep -q "P01" "$root/tmp/list.txt" || fail "the session made before the upgrade is not listed"

echo "fresh_lab_pc: a second session, the export and the analysis, with the new package"
in_root sh -c 'cd /root/lab && monoplane study run --protocol /usr/share/monoplane/protocols/demo.toml \
  --participant P02 --db /root/lab/study.sqlite --headset simulated --observer default \
  --hmd vive --resolution-scale 0.2 --sim-rate 15 --detail low --window off' ||
  fail "the demo session after the upgrade did not complete"
in_root monoplane study export --db /root/lab/study.sqlite --format csv --out /root/lab/study.csv ||
  fail "study export"
[ "$(wc -l < "$root/root/lab/study.csv")" -gt 2 ] || fail "the export has no trials"
in_root monoplane analyze --db /root/lab/study.sqlite --out /root/lab/analysis || fail "analyze"
[ -s "$root/root/lab/analysis/report.html" ] || fail "analyze wrote no report.html"

echo "fresh_lab_pc: remove the package; the study's files stay"
in_root apt-get remove -y -qq monoplane >/dev/null || fail "apt remove"
in_root test ! -e /usr/bin/monoplane || fail "/usr/bin/monoplane is still there after removal"
[ -s "$root/root/lab/study.sqlite" ] || fail "removing the package removed the database"
echo "fresh_lab_pc: passed"
