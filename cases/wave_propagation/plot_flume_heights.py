#!/usr/bin/env python3
"""Generated against requested wave height along a piston flume (moorsph_wave_tank flume).

  plot_flume_heights.py OUT.png T0 T1 LABEL=RUN.csv [LABEL=RUN.csv ...]

Height at each gauge = mean over the whole periods in [T0, T1] of max - min of eta within
each period (wave_heights.py flume prints the same numbers), divided by the requested H;
the band is +-5% of the request.
"""
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from wave_heights import flume_heights


def main(out, t0, t1, runs):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for spec in runs:
        label, path = spec.rsplit('=', 1)
        meta, xs, heights = flume_heights(path, t0, t1)
        ax.plot(xs, heights / (2 * meta['a']), 'o-', ms=4, label=f"{label} ({2 * meta['a'] / meta['dx']:.1f} particles per height)")
    ax.axhspan(0.95, 1.05, color='0.9', label='request +-5%')
    ax.axhline(1.0, color='k', lw=0.8)
    ax.set_xlabel('distance from the piston [m]')
    ax.set_ylabel(f'H / H requested, {t0:g}-{t1:g} s')
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == '__main__':
    main(sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4:])
