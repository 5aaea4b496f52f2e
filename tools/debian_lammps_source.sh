#!/usr/bin/env bash
# Fetch and unpack the LAMMPS source (or another source package's, e.g. kokkos) of one Debian
# suite (sid, forky, trixie, ...), verified:
#   InRelease (signature checked by gpgv against debian-archive-keyring)
#     -> main/source/Sources.xz (SHA256 from InRelease)
#       -> <package>_<version>.orig.tar.* (SHA256 from the package's entry of Sources)
# Only the upstream tarball is unpacked: the development suites' .dsc files are not always on the
# mirror (404), and the plugin needs nothing from Debian's packaging patches. The system's apt
# configuration is left alone (no deb-src entry is added), so `apt-get source lammps` keeps
# meaning the stable suite's LAMMPS.
#
#   tools/debian_lammps_source.sh SUITE DEST [PACKAGE [MARKER]]
# Unpacks into DEST/PACKAGE (replacing it; PACKAGE defaults to lammps) and prints that path on
# the last line. MARKER: a file the source tree holds at its top (default for lammps:
# src/version.h, else CMakeLists.txt). The Debian version is kept in DEST/PACKAGE/.debian-version.
# Environment: ETD_DPD_DEBIAN_MIRROR (default http://deb.debian.org/debian)
set -euo pipefail
suite=${1:?usage: debian_lammps_source.sh SUITE DEST}
dest=${2:?usage: debian_lammps_source.sh SUITE DEST}
package=${3:-lammps}
marker=${4:-}
[ -n "$marker" ] || { [ "$package" = lammps ] && marker=src/version.h || marker=CMakeLists.txt; }
mirror=${ETD_DPD_DEBIAN_MIRROR:-http://deb.debian.org/debian}
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
die() { printf '[etd-dpd] ERROR: %s\n' "$*" >&2; exit 1; }
log() { printf '[etd-dpd] %s\n' "$*" >&2; }
for tool in curl gpgv xz sha256sum tar; do
  command -v "$tool" >/dev/null || die "'$tool' is needed to fetch Debian's $suite $package source"
done
[ -f "$keyring" ] || die "$keyring is missing (Debian package debian-archive-keyring)"

mkdir -p "$dest"
work=$(mktemp -d "$dest/.fetch.XXXXXX")
trap 'rm -rf "$work"' EXIT
fetch() {  # URL FILE: fails with a message naming the URL
  curl -fsSL --retry 3 -o "$2" "$1" || die "could not download $1"
}

fetch "$mirror/dists/$suite/InRelease" "$work/InRelease"
gpgv --keyring "$keyring" --output "$work/Release" "$work/InRelease" 2>"$work/gpgv.log" \
  || { cat "$work/gpgv.log" >&2; die "the signature of Debian's $suite InRelease does not verify"; }
sources_sha=$(awk '/^SHA256:/{s=1; next} /^[^ ]/{s=0} s && $3=="main/source/Sources.xz"{print $1}' \
              "$work/Release")
[ -n "$sources_sha" ] || die "Debian's $suite Release lists no main/source/Sources.xz"
fetch "$mirror/dists/$suite/main/source/Sources.xz" "$work/Sources.xz"
echo "$sources_sha  $work/Sources.xz" | sha256sum -c --quiet - \
  || die "Debian's $suite Sources.xz does not match the SHA256 in its Release file"

# the package's paragraph: its version, pool directory and the SHA256 of the upstream tarball
xz -dc "$work/Sources.xz" | awk -v package="$package" '
  /^Package: / {p = ($2 == package)}
  p && /^Version: / {print "version", $2}
  p && /^Directory: / {print "directory", $2}
  p && /^Checksums-Sha256:/ {c = 1; next}
  p && c && /^ / {if ($3 ~ /\.orig\.tar\./) print "orig", $1, $3; next}
  {c = 0}
  /^$/ {p = 0}' >"$work/package.entry"
version=$(awk '$1=="version"{print $2; exit}' "$work/package.entry")
directory=$(awk '$1=="directory"{print $2; exit}' "$work/package.entry")
read -r _ tar_sha tar_name < <(awk '$1=="orig"' "$work/package.entry" | head -1) || true
[ -n "$version" ] && [ -n "${tar_name:-}" ] \
  || die "Debian's $suite Sources index has no $package source package with an upstream tarball"
log "Debian $suite: $package $version ($tar_name)"

tarball="$dest/$tar_name"
if [ -f "$tarball" ] && echo "$tar_sha  $tarball" | sha256sum -c --quiet - 2>/dev/null; then
  log "reusing $tarball"
else
  log "downloading $mirror/$directory/$tar_name"
  fetch "$mirror/$directory/$tar_name" "$tarball.part"
  echo "$tar_sha  $tarball.part" | sha256sum -c --quiet - \
    || { rm -f "$tarball.part"; die "$tar_name does not match the SHA256 in Debian's $suite Sources"; }
  mv "$tarball.part" "$tarball"
fi

# the upstream tarball may or may not have a top-level folder: unpack, then find the marker
rm -rf "$dest/$package" "$work/unpack"; mkdir -p "$work/unpack"
tar -xf "$tarball" -C "$work/unpack"
top="$work/unpack"
[ -f "$top/$marker" ] || top=$(find "$work/unpack" -mindepth 1 -maxdepth 1 -type d | head -1)
[ -n "$top" ] && [ -f "$top/$marker" ] || die "$tar_name holds no $package source tree (no $marker)"
mv "$top" "$dest/$package"
printf '%s\n' "$version" >"$dest/$package/.debian-version"
echo "$dest/$package"
