#!/usr/bin/env python3
"""Martin & Moyce's (1952) measured surge front in the units of a scene: reads one of
the non-dimensional tables (T = t sqrt(2 g / a), Z = z / a) and writes `time,x` rows
[s, m] for a column of width A [m] whose back wall is at x = X0 [m], the form
`moorsph study --reference FILE` reads (docs/accuracy-cost.md).

    cases/dam_break/martin_moyce_reference.py TABLE A [X0] > front.csv

cases/dam_break/martin_moyce_front_a0.1.csv is this script's output for
cases/dam_break/martin_moyce_2d.yaml (a = 0.1 m, back wall at x = 0) from the a = 2.25 in table.
"""
import math
import sys

G = 9.81


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    table, a = sys.argv[1], float(sys.argv[2])
    x0 = float(sys.argv[3]) if len(sys.argv) == 4 else 0.0
    scale = math.sqrt(2.0 * G / a)  # T per second
    print(f"# from {table}: t = T / sqrt(2 g / a), x = x0 + Z a; a = {a:g} m, x0 = {x0:g} m")
    print("time,x")
    with open(table) as f:
        for number, line in enumerate(f, start=1):
            if line.startswith("#") or line.startswith("T,"):
                continue
            try:
                t, z = (float(v) for v in line.split(","))
            except ValueError:
                sys.exit(f"{table}:{number}: expected 'T,Z'")
            print(f"{t / scale:.5f},{x0 + z * a:.5f}")


if __name__ == "__main__":
    main()
