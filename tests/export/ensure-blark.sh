#!/usr/bin/env bash
# Makes a Python virtual environment with blark (an IEC 61131-3 Structured Text parser) in the
# directory given (the export test passes one under cargo's target/), from the pinned
# tests/export/requirements-blark.txt; prints the path of its `blark` command on stdout.
# Idempotent: reinstalls only when the requirements changed.
#
#   BLARK=$(bash tests/export/ensure-blark.sh target/blark-venv)   # then: "$BLARK" parse file.st
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
venv="${1:?usage: ensure-blark.sh VENV_DIR}"
req="$here/requirements-blark.txt"
say() { echo "ensure-blark: $*" >&2; }
sum=$(sha256sum "$req" | cut -d' ' -f1)
stamp="$venv/.pidlab-req-stamp"
if [ ! -x "$venv/bin/blark" ] || [ "$(cat "$stamp" 2>/dev/null)" != "$sum" ]; then
  say "python3 -m venv $venv; pip install -r $req (once)"
  python3 -m venv "$venv" >&2 || { say "python3 -m venv failed (Debian: apt-get install python3-venv)"; exit 1; }
  "$venv/bin/python" -m pip install --quiet --disable-pip-version-check -r "$req" >&2
  echo "$sum" >"$stamp"
fi
echo "$venv/bin/blark"
