#!/usr/bin/env python3
"""Compares two behaviour snapshots (scripts/snapshot.sh) file by file.

Fields that record wall time, start time, rays per second or thread counts are masked (they
differ between any two runs); everything else must match to the byte. Prints one line per
differing file and exits 1 when any differs.

    scripts/snapshot_diff.py BEFORE_DIR AFTER_DIR
"""
import csv
import io
import json
import os
import re
import sys

VOLATILE_KEY = re.compile(r"(time_s|started_at|threads|rays_per_s|ranks)$")
VOLATILE_TEXT = [
    (re.compile(r"\d{4}-\d\d-\d\d \d\d:\d\d"), "DATE"),
    (re.compile(r"threads=\d+"), "threads=X"),
    (re.compile(r"<td>threads</td><td>[^<]*</td>"), "<td>threads</td><td>X</td>"),
    # a time in seconds or a rate, as the reports and tables print them
    (re.compile(r"\d+(\.\d+)? s\b"), "T s"),
    (re.compile(r"\(\d+(\.\d+)? M rays/s\)"), "(R M rays/s)"),
]


def mask_json(v):
    if isinstance(v, dict):
        return {k: mask_json(x) for k, x in v.items() if not VOLATILE_KEY.search(k)}
    if isinstance(v, list):
        return [mask_json(x) for x in v]
    if isinstance(v, str):
        return mask_text(v)
    return v


def mask_text(s):
    for rx, rep in VOLATILE_TEXT:
        s = rx.sub(rep, s)
    return s


def mask_csv(s):
    rows = list(csv.reader(io.StringIO(s)))
    if not rows:
        return rows
    keep = [i for i, h in enumerate(rows[0]) if not VOLATILE_KEY.search(h)]
    return [[mask_text(r[i]) if i < len(r) else None for i in keep] for r in rows]


def mask_table(s):
    # validate's table: its last column is the case's time in seconds
    return [mask_text(re.sub(r"\s+[\d.]+\s*$", "", line)) for line in s.splitlines()]


def same(a, b, rel):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        da, db = fa.read(), fb.read()
    if da == db:
        return True
    try:
        ta, tb = da.decode(), db.decode()
    except UnicodeDecodeError:
        return False
    if rel.endswith(".json"):
        return mask_json(json.loads(ta)) == mask_json(json.loads(tb))
    if rel.endswith(".csv"):
        return mask_csv(ta) == mask_csv(tb)
    if rel.endswith(".txt"):
        return mask_table(ta) == mask_table(tb)
    if rel.endswith(".html") or rel.endswith(".svg"):
        return mask_text(ta) == mask_text(tb)
    return False


def files(root):
    out = set()
    for d, _, names in os.walk(root):
        for n in names:
            out.add(os.path.relpath(os.path.join(d, n), root))
    return out


def main():
    a, b = sys.argv[1], sys.argv[2]
    fa, fb = files(a), files(b)
    bad = 0
    for rel in sorted(fa | fb):
        if rel not in fb:
            print("missing in after:", rel)
        elif rel not in fa:
            print("new in after:", rel)
        elif not same(os.path.join(a, rel), os.path.join(b, rel), rel):
            print("differs:", rel)
        else:
            continue
        bad += 1
    print(f"{len(fa | fb) - bad} same, {bad} different")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
