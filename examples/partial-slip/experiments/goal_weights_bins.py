#!/usr/bin/python3
"""Bins the IND lines goal-weights-dump.patch writes to stderr (one block per hp step that learns
degrees) by the elements' distance from the contact point in units of a: count, smallest and
largest indicator per dof over the mean, degrees.

    HPX_DUMP=1 build/hpcontact run case.yaml --out R -q 2> ind.txt
    examples/partial-slip/experiments/goal_weights_bins.py ind.txt 0.0196524
"""
import collections
import sys

lines = [l.split() for l in open(sys.argv[1]) if l.startswith("IND")]
a = float(sys.argv[2])
steps, current, previous = [], [], None
for l in lines:  # a step's block runs over body 0, then body 1
    body = int(l[1])
    if previous == 1 and body == 0:
        steps.append(current)
        current = []
    current.append(l)
    previous = body
steps.append(current)
for k, step in enumerate(steps):
    bins = collections.defaultdict(list)
    for l in step:
        r = float(l[3]) / a
        key = "<1.5a" if r < 1.5 else "<3a" if r < 3 else "<10a" if r < 10 else "<100a" if r < 100 else "far"
        bins[key].append((float(l[5]), int(l[4])))
    print(f"learning step {k + 1}:", {key: (len(v), f"{min(x for x, _ in v):.3g}", f"{max(x for x, _ in v):.3g}",
                                            sorted({p for _, p in v})) for key, v in bins.items()})
