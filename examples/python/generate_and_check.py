#!/usr/bin/env python3
"""A test generator in Python feeding random scenes to clash4d.check in a loop.

Each scene has three axis-aligned blocks with random corners and constant
velocities on a grid of halves (so touching, the hard case, is frequent).
For such blocks the answer is known in closed form: on each axis the open
intervals of two blocks overlap while two linear inequalities in t hold, so
the pair's collision times are an open interval (lo, hi) cut from
(t_lo, t_hi), and t* = lo. This script computes that in fractions.Fraction
and holds clash4d's exact answer (verdict and t* of every pair) against it,
and counts where number="double" disagrees with exact.

    PYTHONPATH=build/python python3 examples/python/generate_and_check.py [--seed S] [--cases N]

Prints its seed (rerun with --seed to reproduce) and exits 1 when exact
disagrees with the closed form.
"""
import argparse
import random
import sys
import time
from fractions import Fraction

import clash4d

T_LO, T_HI = 0, 4


def random_block(rng):
    lo = [Fraction(rng.randint(-4, 4), 2) for _ in range(3)]
    hi = [x + Fraction(rng.randint(1, 4), 2) for x in lo]
    v = [Fraction(rng.randint(-2, 2), 2) for _ in range(3)]
    return lo, hi, v


def pair_interval(a, b):
    """The open interval of times in (T_LO, T_HI) when a and b overlap, or None."""
    lo, hi = Fraction(T_LO), Fraction(T_HI)
    (alo, ahi, va), (blo, bhi, vb) = a, b
    for i in range(3):
        # (alo + va t) - (bhi + vb t) < 0 and (blo + vb t) - (ahi + va t) < 0
        for c0, c1 in ((alo[i] - bhi[i], va[i] - vb[i]), (blo[i] - ahi[i], vb[i] - va[i])):
            if c1 == 0:
                if c0 >= 0:
                    return None
            elif c1 > 0:
                hi = min(hi, -c0 / c1)    # t < -c0 / c1
            else:
                lo = max(lo, -c0 / c1)    # t > -c0 / c1
    return (lo, hi) if lo < hi else None


def scene_of(blocks):
    objects = []
    for name, (lo, hi, v) in zip("abc", blocks):
        objects.append({"name": name, "shape": {"block": {"min": lo, "max": hi}},   # Fractions, read exactly
                        "motion": "vel %s %s %s" % tuple(v)})
    return {"format": "clash4d-scene/1", "name": "generated", "time": [T_LO, T_HI], "objects": objects}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seed", type=int, default=int(time.time()))
    parser.add_argument("--cases", type=int, default=100)
    args = parser.parse_args()
    print("generate_and_check: seed %d, %d cases (clash4d %s)" % (args.seed, args.cases, clash4d.__version__))
    rng = random.Random(args.seed)
    wrong = double_disagrees = colliding = 0
    for case in range(args.cases):
        blocks = [random_block(rng) for _ in range(3)]
        scene = scene_of(blocks)
        expected = {}
        for i in range(3):
            for j in range(i + 1, 3):
                interval = pair_interval(blocks[i], blocks[j])
                if interval:
                    expected[("abc"[i], "abc"[j])] = interval[0]
        exact = clash4d.check(scene, earliest=True, all_pairs=True)
        got = {p.objects: p.t for p in exact.pairs}
        if got != expected or exact.collide != bool(expected):
            wrong += 1
            print("case %d: exact %s, closed form %s\n%s" % (case, got, expected, clash4d.scene_json(scene)))
        colliding += bool(expected)
        double = clash4d.check(scene, number="double", all_pairs=True)
        if {p.objects for p in double.pairs} != set(got):
            double_disagrees += 1
            print("case %d: double's colliding pairs %s, exact's %s" % (case, sorted(p.objects for p in double.pairs), sorted(got)))
    print("%d cases (%d colliding): exact disagrees with the closed form on %d, double with exact on %d"
          % (args.cases, colliding, wrong, double_disagrees))
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
