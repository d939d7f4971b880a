#!/usr/bin/env bash
# Fetch the pinned Blockly release from npm, check its integrity hash and unpack
# only the files the editor page needs into resources/blockly/vendor/.
set -euo pipefail

version=13.3.0
integrity='sha512-qAHFGMGTSF67Lupr3pjZz9LQu4JCFdN76CMZxegBKiveZreK08yXhaCz0g9q9/xe5GEdoeFT3POAlQavPIRPEw=='

here=$(cd "$(dirname "$0")/.." && pwd)
dest="$here/resources/blockly/vendor"
stamp="$dest/.version"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$version" ]; then touch "$stamp"; exit 0; fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! (cd "$work" && npm pack --silent "blockly@$version" >/dev/null); then
  echo "Could not fetch Blockly $version with npm pack (is the npm registry reachable?)" >&2
  exit 1
fi
tarball="$work/blockly-$version.tgz"
actual="sha512-$(python3 -c 'import base64, hashlib, sys; print(base64.b64encode(hashlib.sha512(open(sys.argv[1], "rb").read()).digest()).decode())' "$tarball")"
if [ "$actual" != "$integrity" ]; then
  echo "Blockly tarball integrity mismatch: expected $integrity, got $actual" >&2
  exit 1
fi
tar -xzf "$tarball" -C "$work"
rm -rf "$dest.tmp" && mkdir -p "$dest.tmp/msg"
cp "$work/package/blockly_compressed.js" "$work/package/blocks_compressed.js" \
   "$work/package/python_compressed.js" "$work/package/LICENSE" "$dest.tmp/"
cp "$work/package/msg/en.js" "$work/package/msg/de.js" "$dest.tmp/msg/"
cp -r "$work/package/media" "$dest.tmp/media"
echo "$version" > "$dest.tmp/.version"
rm -rf "$dest" && mv "$dest.tmp" "$dest"
echo "Blockly $version unpacked into resources/blockly/vendor"
