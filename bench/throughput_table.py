#!/usr/bin/env python3
"""Format the output of bench/run_throughput.sh as the markdown table of docs/performance.md.

Usage: bench/run_throughput.sh build | tee bench.txt; /usr/bin/python3 bench/throughput_table.py bench.txt
"""
import re
import sys


def parse(path):
    rows = []
    for line in open(path):
        if not re.match(r"^[23]D particles=", line):
            continue
        fields = dict(f.split("=", 1) for f in line.split()[1:])
        fields["dim"] = line[:2]
        rows.append(fields)
    return rows


def main():
    rows = parse(sys.argv[1])
    rate1 = {}
    for r in rows:
        if r["threads"] == "1":
            rate1[(r["dim"], r["particles"])] = float(r["particle_steps_per_s"])
    print("| case | particles | neighbours | threads | steps | wall s | particle-steps/s | "
          "interactions/s | ns/particle-step | bytes/particle | parallel efficiency |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        key = (r["dim"], r["particles"])
        eff = ""
        if r["threads"] == "2" and key in rate1:
            eff = "%.2f" % (float(r["particle_steps_per_s"]) / (2 * rate1[key]))
        print("| %s dam break | %s | %s | %s | %s | %s | %.3g | %.3g | %s | %s | %s |" % (
            r["dim"], r["particles"], r["neighbours"], r["threads"], r["steps"], r["wall_s"],
            float(r["particle_steps_per_s"]), float(r["interactions_per_s"]), r["ns_per_particle_step"],
            r["bytes_per_particle"], eff))


if __name__ == "__main__":
    main()
