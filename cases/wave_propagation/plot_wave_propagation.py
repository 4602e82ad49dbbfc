#!/usr/bin/env python3
"""Height against distance travelled for periodic free-decay runs of moorsph_wave_tank.

  plot_wave_propagation.py OUT.png T0 LABEL=RUN.csv [LABEL=RUN.csv ...]

T0 is the time the forcing stopped [s]. The distance is the group speed times the time
since then (wave_heights.py explains the equivalence with a flume); the dashed line is
the 5% loss the validation asks for at 10 wavelengths.
"""
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

from wave_heights import group_speed, period_heights, read


def main(out, t0, runs):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for spec in runs:
        label, path = spec.rsplit('=', 1)
        meta, t, xs, eta = read(path)
        cg, _ = group_speed(meta['T'], meta['depth'])
        rows = period_heights(t, eta, meta['T'], t0)
        h0 = rows[0][1]
        dist = [cg * (a + 0.5 * meta['T'] - t0) / meta['lambda'] for a, _ in rows]
        ax.plot(dist, [h / h0 for _, h in rows], 'o-', ms=3, label=f"{label} (H0/dx = {h0 / meta['dx']:.1f})")
    ax.axhline(0.95, color='k', ls='--', lw=0.8, label='5% loss')
    ax.set_xlabel('distance travelled at the group speed [wavelengths]')
    ax.set_ylabel('H / H at the start')
    ax.set_ylim(0, 1.1)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == '__main__':
    main(sys.argv[1], float(sys.argv[2]), sys.argv[3:])
