#!/usr/bin/env python3
"""cases/ship/make_variants.py: the committed variant scenes are what it writes from
ship_base.yaml (a base edited without rerunning it fails here), and a restart variant it
writes at another spacing differs from that spacing's base in exactly the lines in which
the 4 m variant differs from the 4 m base (the variant's change, nothing of the spacing's
lost or doubled)."""
import difflib
import glob
import os
import shutil
import subprocess
import sys
import tempfile

SHIP = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "cases", "ship")


def body(path):
    text = open(path).read()
    return text[text.index("dim: 3"):].splitlines()


def changed(a, b):
    """The lines removed from a and added in b, the variant's name line left out."""
    out = set()
    for line in difflib.unified_diff(a, b, lineterm="", n=0):
        if line[:1] in "+-" and not line.startswith(("+++", "---")) and not line[1:].startswith("name:"):
            out.add(line)
    return out


def main():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        for f in glob.glob(os.path.join(SHIP, "*")):
            if f.endswith((".yaml", ".csv", ".stl", ".py")):
                shutil.copy(f, tmp)
        run = subprocess.run([sys.executable, "make_variants.py"], cwd=tmp, capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"make_variants.py failed: {run.stderr}")
        written = [line.split()[1] for line in run.stdout.splitlines() if line.startswith("wrote ")]
        if len(written) < 10:
            failures.append(f"only {len(written)} scenes written: {written}")
        for name in written:
            if open(os.path.join(tmp, name)).read() != open(os.path.join(SHIP, name)).read():
                failures.append(f"{name}: the committed file is not what make_variants.py writes (rerun it)")

        out = os.path.join(tmp, "at6")
        run = subprocess.run([sys.executable, "make_variants.py", "--restart-variants-at", "6", "696", out],
                             cwd=tmp, capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"make_variants.py --restart-variants-at failed: {run.stderr}")
        base4, base6 = body(os.path.join(SHIP, "ship_base.yaml")), body(os.path.join(SHIP, "ship_dx6.yaml"))
        variants = sorted(glob.glob(os.path.join(out, "ship_*_dx6.yaml")))
        if len(variants) != 5:
            failures.append(f"expected 5 restart variants at 6 m, got {variants}")
        for v6 in variants:
            name = os.path.basename(v6).replace("_dx6.yaml", "")
            want = changed(base4, body(os.path.join(SHIP, name + ".yaml")))
            got = changed(base6, body(v6))
            if not want or got != want:
                failures.append(f"{name} at 6 m: changes against ship_dx6.yaml {sorted(got ^ want)} differ from the 4 m variant's")
            if f"name: {name}_dx6" not in body(v6):
                failures.append(f"{name} at 6 m is not named {name}_dx6")
        for used in ("signal_order1.csv", "hull_blunt.stl", "hull_deck.csv"):
            if not os.path.exists(os.path.join(out, used)):
                failures.append(f"{used} not written beside the 6 m variants")
    if failures:
        sys.exit("\n".join(failures))
    print(f"{len(written)} variant scenes current; {len(variants)} restart variants at 6 m change what the 4 m ones do")


if __name__ == "__main__":
    main()
