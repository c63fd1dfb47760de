#!/usr/bin/env bash
# Makes .venv (a local Python virtual environment) with python-control, for the export tests and
# the benchmark's comparison; prints the interpreter's path on stdout. Idempotent: reinstalls only
# when scripts/requirements-python.txt changed. A new machine has Python 3 (with venv and pip).
#
#   PY=$(bash scripts/ensure-python.sh)   # then: "$PY" -c 'import control'
set -euo pipefail
cd "$(dirname "$0")/.."
say() { echo "ensure-python: $*" >&2; }
req=scripts/requirements-python.txt
stamp=.venv/.pidlab-req-stamp
sum=$(sha256sum "$req" | cut -d' ' -f1)
if [ ! -x .venv/bin/python ] || [ "$(cat "$stamp" 2>/dev/null)" != "$sum" ]; then
  say "python3 -m venv .venv; pip install -r $req (once, ~1 min)"
  python3 -m venv .venv >&2 || { say "python3 -m venv failed (Debian: apt-get install python3-venv)"; exit 1; }
  .venv/bin/python -m pip install --quiet --disable-pip-version-check -r "$req" >&2
  echo "$sum" >"$stamp"
fi
.venv/bin/python -c 'import control' >&2
echo "$PWD/.venv/bin/python"
