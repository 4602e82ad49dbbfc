#!/usr/bin/env python3
"""Split the MARIN measurements of SPHERIC Test 2 (Kleefsman et al. 2005) into one
`time,value` CSV per column (P1-P8 in Pa, H1-H4 in m), the form
`moorsph study --reference FILE` reads (docs/accuracy-cost.md).

    cases/spheric_test2/reference_csv.py [DATA] [OUTDIR]

DATA defaults to ../shared/refdata/spheric_test2_kleefsman/test_case_2_exp_data.dat,
OUTDIR to runs/spheric_test2_reference.
"""
import os
import sys

COLUMNS = ["P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8", "H1", "H2", "H3", "H4"]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    data = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "../../../shared/refdata/spheric_test2_kleefsman/test_case_2_exp_data.dat")
    out = sys.argv[2] if len(sys.argv) > 2 else "runs/spheric_test2_reference"
    rows = []
    with open(data) as f:
        header = f.readline().split()
        if header[:2] != ["Time", "(s)"]:
            sys.exit(f"{data}:1: expected the header 'Time (s) P1 (Pa) ...', got {' '.join(header[:4])}")
        for number, line in enumerate(f, start=2):
            fields = line.split()
            if not fields:
                continue
            if len(fields) != 1 + len(COLUMNS):
                sys.exit(f"{data}:{number}: expected {1 + len(COLUMNS)} columns, got {len(fields)}")
            rows.append([float(x) for x in fields])
    os.makedirs(out, exist_ok=True)
    for i, name in enumerate(COLUMNS):
        with open(os.path.join(out, name + ".csv"), "w") as f:
            f.write(f"time,{name}\n")
            for r in rows:
                f.write(f"{r[0]:.7g},{r[1 + i]:.7g}\n")
    print(f"{len(rows)} rows, t = {rows[0][0]:.4g} .. {rows[-1][0]:.4g} s -> {out}/{{P1..P8,H1..H4}}.csv")


if __name__ == "__main__":
    main()
