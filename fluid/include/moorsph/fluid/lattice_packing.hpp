#pragma once
// Packed start: relaxes a freshly filled block of water from its cubic lattice into an
// even, disordered arrangement before the run starts.
//
// Why: on the simple cubic lattice the kernel sum dx^D sum_j W_ij is 1.0175 in 3D
// (h = 1.2 dx), about 1.00 once the particles are disordered (docs/stability.md,
// "why the 3D water does not settle"). The lattice does not survive a run: round-off
// and the walls disorder it, continuity lowers every particle's density with the kernel
// sum, gravity recompresses the column and the released potential energy becomes noise.
// A 132 m column at dx = 4 m packs down 1.2-1.3 m that way (docs/validation/ship.md),
// which lowers a moored ship and slackens its cables by 5-10%. Starting from a packed
// arrangement at the same number of particles in the same volume removes that collapse.
//
// How: gradient descent on the particle concentration C_i = dx^D sum_j W_ij over the
// block's own particles (Colagrossi et al. 2012, Comput. Phys. Commun. 183:1641, pack
// by a fictitious flow down grad C; the same gradient drives particle shifting, Lind et
// al. 2012):
//
//   r_i <- r_i - step h^2 grad C_i,   |shift| <= max_shift dx per iteration       (1)
//
// after a seeded random jitter that breaks the lattice's symmetry (on a perfect lattice
// grad C = 0). The block's faces are mirror planes (its own particles' images across
// each face, and across two or three faces at edges and corners), so the water next to
// a wall or at the still surface keeps a full kernel and stays flat; faces along a
// periodic axis that the block spans are left open (the periodic images stand in).
// Particles are kept inside the block. The packing sees no walls, bodies or obstacles:
// pack first, then drop the particles inside solids, as for the lattice.
// The caller sets the densities afterwards (hydrostatic for the new heights).
#include <cstdint>
#include <vector>
#include <moorsph/fluid/domain.hpp>
#include <moorsph/fluid/fluid_particles.hpp>
#include <moorsph/fluid/fluid_setup.hpp>

namespace moorsph::fluid {

struct PackingSpec {
  int iterations = 400;      ///< descent iterations of (1)
  double jitter = 0.1;       ///< initial random displacement, each component uniform in +-jitter dx
  double step = 0.5;         ///< descent step of (1) [-]
  double max_shift = 0.05;   ///< largest move per iteration [dx]
  std::uint64_t seed = 1;    ///< jitter seed (the same seed gives the same start)
};

/// What the packing did: the concentration C (mean and rms spread over the block's
/// interior, particles at least 2h from every mirror face) before and after, and the
/// rms move of the last iteration [dx].
struct PackingReport {
  int iterations = 0;
  double mean_before = 0.0, spread_before = 0.0;
  double mean_after = 0.0, spread_after = 0.0;
  double last_rms_shift = 0.0;
};

/// Pack `block` (all of it: one water block of spacing dx) inside [lower, upper].
/// `domain` gives the periodic axes (a face on a periodic axis that the block spans
/// is open); `h` is the smoothing length.
template <int D>
PackingReport packBlock(FluidParticles<D>& block, const Vec<D>& lower, const Vec<D>& upper, const Domain<D>& domain,
                        double dx, double h, const PackingSpec& spec);

/// The faces of [lower, upper] that are mirrors for packBlock.
template <int D>
std::vector<MirrorPlane> packingMirrors(const Vec<D>& lower, const Vec<D>& upper, const Domain<D>& domain);

}  // namespace moorsph::fluid
