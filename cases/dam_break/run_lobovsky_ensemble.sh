#!/usr/bin/env bash
# The Lobovsky et al. (2014) dam break at one spacing, run eight times with details that
# should not matter (the time step, the integrator), against the measured sensor-2 pressure
# (docs/validation/lobovsky-dam-break.md, "one run is one draw"):
#   cases/dam_break/run_lobovsky_ensemble.sh BUILD OUT DX [THREADS]
#   e.g. cases/dam_break/run_lobovsky_ensemble.sh build runs/lobovsky_ensemble 0.005 1
# Members: predictor-corrector at CFL 0.2 / 0.25 / 0.3 / 0.35 and symplectic at
# CFL 0.2 / 0.3 / 0.4 / 0.5, each to t = 1.0 s (t/T = 5.7, past the plateau window).
# Writes OUT/MEMBER/ (the runs; existing ones are kept) and OUT/ensemble.{md,png}.
set -euo pipefail
build=$1 out=$2 dx=$3 threads=${4:-1}
here=$(cd "$(dirname "$0")" && pwd)
scene="$here/lobovsky_h300_2d.yaml"
export OMP_WAIT_POLICY=passive
mkdir -p "$out"
member() {  # member NAME INTEGRATOR CFL
  [ -f "$out/$1/log.txt" ] && grep -q '^simulated ' "$out/$1/log.txt" && return 0
  "$build/app/moorsph" run "$scene" --threads "$threads" --out "$out/$1" --end 1.0 \
    --set resolution.dx="$dx" --set resolution.boundary_spacing="$dx" --set output.particles_interval=0 \
    --set method.integrator="$2" --set method.cfl="$3" > "$out/$1.log" 2>&1 ||
    echo "member $1 stopped (kept out of the ensemble): see $out/$1.log"
}
for cfl in 0.2 0.25 0.3 0.35; do member "pc_cfl$cfl" predictor_corrector "$cfl"; done
for cfl in 0.2 0.3 0.4 0.5; do member "symplectic_cfl$cfl" symplectic "$cfl"; done
/usr/bin/python3 "$here/lobovsky_report.py" ensemble --out "$out/ensemble" "$out"/*/
