#!/usr/bin/env bash
# The package test (run by CTest when dpkg-deb is present): builds the .deb
# and the .tar.gz from a build directory, checks what the .deb holds (the executables, the desktop
# entry with desktop-file-validate, the AppStream metainfo with appstreamcli
# where installed, the icons, man page, udev rules, profiles and the
# dependencies dpkg-shlibdeps computed), installs it with dpkg into a
# temporary root and runs `tactiscope-cli --version` from there.
#
# Usage: installer/test-package.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "test-package: $*" >&2; exit 1; }

(cd "$build" && cpack -G "DEB;TGZ" -B "$work/out" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log" >&2; fail "cpack failed"; }
deb=$(ls "$work"/out/*.deb)
tarball=$(ls "$work"/out/*.tar.gz)
echo "test-package: built $(basename "$deb") and $(basename "$tarball")"
# The tarball is the same tree under one top folder.
listing=$(tar tzf "$tarball")
for path in usr/bin/tactiscope usr/bin/tactiscope-cli usr/lib/udev/rules.d/70-tactiscope-probes.rules; do
  grep -qE "^[^/]+/$path\$" <<<"$listing" || fail "the tarball lacks $path"
done

contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for path in \
  ./usr/bin/tactiscope \
  ./usr/bin/tactiscope-cli \
  ./usr/share/applications/org.tactiscope.Tactiscope.desktop \
  ./usr/share/metainfo/org.tactiscope.Tactiscope.metainfo.xml \
  ./usr/share/icons/hicolor/scalable/apps/tactiscope.svg \
  ./usr/share/icons/hicolor/16x16/apps/tactiscope.png \
  ./usr/share/icons/hicolor/48x48/apps/tactiscope.png \
  ./usr/share/icons/hicolor/256x256/apps/tactiscope.png \
  ./usr/share/man/man1/tactiscope-cli.1.gz \
  ./usr/lib/udev/rules.d/70-tactiscope-probes.rules \
  ./usr/share/tactiscope/reference-tissues.json \
  ./usr/share/tactiscope/profiles/compliance-probe-paper.json \
  ./usr/share/tactiscope/profiles/capacitive-beam-paper-no1.json \
  ./usr/share/doc/tactiscope/copyright \
  ./usr/share/doc/tactiscope/user-guide.md; do
  grep -qxF "$path" <<<"$contents" || fail "the package lacks $path"
done

depends=$(dpkg-deb -f "$deb" Depends)
for library in libqt6widgets6 libqt6svg6 libsqlite3-0 libhidapi-hidraw0 libserialport0 libqcustomplot; do
  grep -q "$library" <<<"$depends" || fail "Depends lacks $library: $depends"
done
echo "test-package: Depends: $depends"

root="$work/root"
mkdir -p "$root/var/lib/dpkg/info" "$root/var/lib/dpkg/updates"
touch "$root/var/lib/dpkg/status"
# The empty root has none of the libraries, so their absence is forced; the
# binaries then run against this system's.
dpkg --root="$root" --force-not-root --force-depends --force-script-chrootless --log=/dev/null \
  -i "$deb" >"$work/dpkg.log" 2>&1 || { cat "$work/dpkg.log" >&2; fail "dpkg could not install the package"; }

desktop-file-validate "$root/usr/share/applications/org.tactiscope.Tactiscope.desktop" ||
  fail "the desktop entry is not valid"
if command -v appstreamcli >/dev/null; then
  appstreamcli validate --no-net "$root/usr/share/metainfo/org.tactiscope.Tactiscope.metainfo.xml" ||
    fail "the AppStream metainfo is not valid"
fi
grep -q '^\.TH TACTISCOPE-CLI 1' <<<"$(zcat "$root/usr/share/man/man1/tactiscope-cli.1.gz")" || fail "the man page is not one"

version=$("$root/usr/bin/tactiscope-cli" --version) || fail "the installed tactiscope-cli does not run"
grep -q "^tactiscope-cli " <<<"$version" || fail "unexpected --version output: $version"
echo "test-package: installed into a temporary root; $version"
