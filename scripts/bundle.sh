#!/usr/bin/env bash
# The offline classroom bundle: dist/pidlab-classroom.zip with pidlab.html (the whole page in one
# file, scripts/build-page.sh) and index.html (example embeddings in instructor mode and a
# postMessage demonstration, scripts/bundle-index.mjs). Unzip anywhere and open index.html.
#   bash scripts/bundle.sh            # builds dist/pidlab.html first when it is missing
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
if [ ! -f dist/pidlab.html ]; then
  bash scripts/build-page.sh
fi
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/pidlab-classroom"
cp dist/pidlab.html "$stage/pidlab-classroom/pidlab.html"
node scripts/bundle-index.mjs "$stage/pidlab-classroom/index.html"
rm -f dist/pidlab-classroom.zip
# python's zipfile rather than zip(1): python 3 is already required (scripts/ensure-tools.sh)
(cd "$stage" && python3 -m zipfile -c pidlab-classroom.zip pidlab-classroom/)
mv "$stage/pidlab-classroom.zip" dist/pidlab-classroom.zip
echo "wrote dist/pidlab-classroom.zip ($(du -k dist/pidlab-classroom.zip | cut -f1) KiB): pidlab-classroom/{pidlab.html,index.html}"
