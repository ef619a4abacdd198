#!/usr/bin/env python3
"""Compares two folders of scripts/compare-outputs.sh (two builds' outputs): every file byte for
byte after masking the checkout's path (ROOT) and, in standard error, the progress lines a loaded
machine makes differ (surrogates done, solver iterations, tabulation passes, times); a JSON file
that still differs is compared as data (keys and values, not their order).
  python3 scripts/compare_outputs.py OUT_BEFORE OUT_AFTER [--diff]
Prints each file that differs (--diff: its lines) and a count; exit status 1 if any differs."""
import json
import os
import re
import sys

PROGRESS = re.compile(r"surrogate surfaces, about|\d+/\d+ (load steps|surrogate)|s left$|pressures solved|"
                      r"step \d+/\d+: |integrat|, T s$")


def files(root):
    found = set()
    for folder, _, names in os.walk(root):
        for name in names:
            found.add(os.path.relpath(os.path.join(folder, name), root))
    return found


def normalised(path, name):
    text = open(path, "rb").read().decode("utf-8", "replace")
    text = re.sub(r"/(work/main|tmp/wt-[a-z]+)", "ROOT", text)  # the checkouts this was run from
    text = re.sub(re.escape(os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))), "ROOT", text)
    if name.endswith(".err"):
        text = "\n".join(line for line in text.split("\n") if not PROGRESS.search(line))
    return text


def main():
    before, after = sys.argv[1], sys.argv[2]
    show = "--diff" in sys.argv[3:]
    a, b = files(before), files(after)
    for name in sorted(a - b):
        print("only before:", name)
    for name in sorted(b - a):
        print("only after:", name)
    same = as_data = differ = 0
    for name in sorted(a & b):
        x, y = normalised(os.path.join(before, name), name), normalised(os.path.join(after, name), name)
        if x == y:
            same += 1
        elif name.endswith(".json") and json.loads(x) == json.loads(y):
            as_data += 1
            print("equal as JSON data, keys in another order:", name)
        else:
            differ += 1
            print("differs:", name)
            if show:
                xs, ys = x.split("\n"), y.split("\n")
                for line in xs:
                    if line not in ys:
                        print("  <", line[:300])
                for line in ys:
                    if line not in xs:
                        print("  >", line[:300])
    print(f"{same} identical, {as_data} equal as JSON data, {differ} differ, of {len(a & b)} files in both")
    return 1 if differ or a != b else 0


if __name__ == "__main__":
    sys.exit(main())
