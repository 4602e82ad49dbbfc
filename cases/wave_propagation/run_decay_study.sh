#!/bin/sh
# Wave propagation study (issue 6 item 4, docs/validation/wave-propagation.md): a regular
# wave (T = 0.836 s, depth 0.25 m, lambda = 1.0 m, H = 0.05 m) is made by a forcing region
# over a periodic tank of one wavelength, the forcing stops at t = 2.5 s, and the wave
# runs freely to t = 9 s (4.1 wavelengths at the group speed) or END. Each run writes
# OUTDIR/<name>.csv; wave_heights.py and plot_wave_propagation.py read them.
#
#   run_decay_study.sh BUILD_DIR OUTDIR [END]
#
# Runs one after another on one thread (OMP_WAIT_POLICY=passive): about 1-6 wall minutes
# each at dx = 12.5 mm (3.4 particles per wave height), 25 at dx = 6.25 mm, 26 at 5 mm
# (measured on a 2-vCPU machine shared with other jobs).
set -e
B="$1/cases/wave_propagation/moorsph_wave_tank"
OUT="$2"
END="${3:-9}"
mkdir -p "$OUT"
export OMP_WAIT_POLICY=passive
C="periodic amplitude=0.025 ramp_up=1 forcing_end=2.5 end=$END"
run() { name="$1"; shift; echo "== $name: $*"; "$B" $C "$@" --out "$OUT/$name.csv" | tee "$OUT/$name.log"; }
run ref dx=0.0125
run monaghan dx=0.0125 xsph_form=monaghan
run no_xsph dx=0.0125 xsph_eps=0
run no_viscosity dx=0.0125 no_viscosity=1
run density_diffusion dx=0.0125 density_diffusion=1
run midpoint_dd dx=0.0125 predictor_fraction=0.5 density_diffusion=1
run cfl025 dx=0.0125 cfl=0.25
run dd_cfl025 dx=0.0125 density_diffusion=1 cfl=0.25
run h15_dd dx=0.0125 h_factor=1.5 density_diffusion=1
run all_options dx=0.0125 density_diffusion=1 predictor_fraction=0.5 cfl=0.25 h_factor=1.5
run deep dx=0.0125 depth=0.5
run fine dx=0.00625
run ten_per_height dx=0.005
