"""moorsph plot: PNG plots of every time series of a run directory.

Usage: python3 plot_series.py RUN_DIR
Writes RUN_DIR/plots/<group>.png: one panel per column of the group (gauges, probes,
energy, timing, ...) against time, each axis labelled with its SI units.
Exit 0: plots written; 2: no series.h5; 77: h5py or matplotlib missing.
"""
import os
import sys

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")  # files only, no display needed
    import matplotlib.pyplot as plt
except ImportError as error:
    print(f"moorsph plot needs h5py and matplotlib in {sys.executable} "
          f"(Debian: apt-get install python3-h5py python3-matplotlib): {error}")
    sys.exit(77)


def units(dataset):
    value = dataset.attrs.get("units", b"")
    return value.decode() if isinstance(value, bytes) else str(value)


def main(run):
    path = os.path.join(run, "series.h5")
    if not os.path.exists(path):
        print(f"{path}: no such file (is {run} a run directory?)")
        return 2
    out = os.path.join(run, "plots")
    os.makedirs(out, exist_ok=True)
    written = []
    with h5py.File(path, "r") as f:
        for name, group in f.items():
            columns = [c for c in group if c != "time"]
            if not columns or "time" not in group:
                continue
            rows = min(group[c].shape[0] for c in columns + ["time"])  # a killed run may differ by one
            t = group["time"][:rows]
            fig, axes = plt.subplots(len(columns), 1, sharex=True, squeeze=False,
                                     figsize=(8, 1.8 + 1.6 * len(columns)))
            for ax, column in zip(axes[:, 0], columns):
                ax.plot(t, group[column][:rows], lw=1.0)
                ax.set_ylabel(f"{column} [{units(group[column])}]", fontsize=8)
                ax.grid(alpha=0.3)
            axes[-1, 0].set_xlabel("time [s]")
            description = group.attrs.get("description", b"")
            if isinstance(description, bytes):
                description = description.decode()
            fig.suptitle(f"{name}: {description}" if description else name, fontsize=9)
            fig.tight_layout()
            target = os.path.join(out, f"{name}.png")
            fig.savefig(target, dpi=100)
            plt.close(fig)
            written.append(target)
    print(f"wrote {len(written)} plots to {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
