"""Parses IEC 61131-3 Structured Text files with blark (one process, the grammar loaded once).

Usage: python parse_st.py FILE...  Prints "ok FILE" or "error FILE: message" per file; the exit
status is 1 when any file fails to parse.
"""
import sys

from blark.parse import parse_source_code


def main(paths):
    bad = 0
    for p in paths:
        with open(p, encoding="utf-8") as f:
            res = parse_source_code(f.read(), fn=p)
        if res.exception is not None:
            bad += 1
            msg = " ".join(str(res.exception).split())[:300]
            print("error %s: %s" % (p, msg))
        else:
            print("ok %s" % p)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
