#pragma once
// The force of one boundary particle k on one fluid particle i (METHOD.md section 2):
//
//   F_ik / m_i = (strength c_s^2 / h) B(r_par) S(q) n_k,   q = (r_perp . n_k + b_off dx) / h
//   S(q) = (0.8/q)^8            0 < q <= 0.8        (s = 8, d = 1: s d/(s+2) = 0.8)
//          25 (q - 1)^2         0.8 <= q <= 1       ((s+2)/(2d))^2 = 25
//          0                    otherwise, also behind the (offset) wall
//   B(r_par) = 1 - |r_par|/dx   for |r_par| <= dx, else 0
//
// S is continuous with a continuous slope at q = 0.8 (both branches give 1 and -10).
// Deviation from METHOD.md: behind the boundary particle's plane (r_perp . n_k < 0) q is
// taken at r_perp . n_k = 0, so the force is bounded by S(b_off dx / h) (see alongNormal).
// A corner particle with several normals pushes a fluid particle that is in front of
// two or more of them along the single effective normal pointing straight at it
// from the corner; in front of exactly one, that normal acts alone. "Straight at it"
// is taken perpendicular to the corner's edge line: r_perp is the part of r_ik in the
// span of the normals the particle faces, r_par the rest (along a 3D edge), and B
// applies to r_par as on a flat wall. In 2D corners and 3D vertices the span is the
// whole space, so r_perp = r_ik and B = 1 as METHOD.md says. (Pushing radially from
// every particle of a 3D edge line instead throws particles near the line sideways
// with unbounded force; that instability was observed in a 3D hydrostatic tank.)
//
// Beyond an edge: a fluid particle behind a single-normal particle k's plane is usually
// outside the body, beyond a convex edge of it or on the far side of a part thinner than
// the kernel (a blunt bow 1 dx wide, a plate), not through the wall; there k's held push
// would throw it at the body (0.57 c_s in the heavy-ship stability case). beyondEdge
// tells the two apart with a second particle k2 of the same surface within 2h: the fluid
// particle is in front of k2 along a normal n2 of another face (n2 . n_k < cos 45 deg)
// and the two faces meet convexly: with t the part of n2 in k's plane, k lies on the -t
// side of k2 (faces back to back, t ~ 0: k2 lies behind k's plane). Through a flat or
// convex wall a particle is behind every nearby particle's plane; through a concave
// corner (a tank's side wall above its floor, or the floor beside the corner particle)
// k lies on the +t side of k2: both keep their push. In front of k's plane the same
// holds near a convex edge when the fluid particle is also past k2 along t (beyond the
// edge line, where a face particle within dx of the edge pushes it at nearly the on-plane
// strength along the wrong normal; the edge particles' own corner rule pushes it off the
// edge instead). A smooth convex surface is not affected: there k2 lies past the fluid
// particle along t.
//
// The boundary particle feels -F_ik: walls() sums these reactions for the wrench on a
// body and for pressure sensors. The same function is evaluated on both sides, so
// action and reaction are equal to the last bit.
//
// Conservative form (method.boundary_force: conservative). The law above pushes along
// n_k only, but its size depends on r_par through B: it is not the gradient of any
// potential, so a fluid particle taken round a closed path near the wall (in at one
// r_par, out at another) gains or loses work. Coupled to a free body this is a
// circulatory (non-symmetric) stiffness, the classic cause of flutter: the tethered lab
// buoy at rest swayed and rocked with an amplitude growing ~e^(7 t) from round-off
// (docs/validation/tethered-buoy.md). The conservative form is minus the gradient of
//   Phi_ik / m_i = strength c_s^2 B(r_par) Psi(q),   Psi(q) = int_q^1 S(q') dq',
// whose normal part is the law above (dPsi/dr_perp = -S/h) and whose part along the
// wall, strength c_s^2 (Psi / dx) r_par/|r_par|, pushes the fluid particle away from k
// along the wall (about a tenth of the normal push; it sums to zero along a flat 2D
// wall, where the B sum to one). Behind the plane, where the
// push is held, Psi continues linearly. The body then takes each reaction's moment at
// the fluid particle (walls.cpp), the torque that conserves the pair's angular momentum
// and so the energy of a rotating body.
#include <algorithm>
#include <cmath>
#include <limits>
#include <moorsph/fluid/boundary_particles.hpp>

namespace moorsph::fluid {

template <int D>
class BoundaryForceLaw {
 public:
  BoundaryForceLaw(double strength, double sound_speed, double h, double dx, double b_off,
                   bool conservative = false)
      : scale_(strength * sound_speed * sound_speed / h), inv_h_(1.0 / h), dx_(dx), inv_dx_(1.0 / dx),
        offset_(b_off * dx), conservative_(conservative) {}

  bool conservative() const { return conservative_; }

  /// S(q) of METHOD.md section 2.
  static double shape(double q) {
    if (q <= 0.0 || q >= 1.0) return 0.0;
    if (q < 0.8) {
      const double a = 0.8 / q;
      const double a2 = a * a;
      const double a4 = a2 * a2;
      return a4 * a4;
    }
    const double b = q - 1.0;
    return 25.0 * b * b;
  }

  /// Psi(q) = int_q^1 S(q') dq', the potential of the conservative form.
  static double potential(double q) {
    if (q <= 0.0) return std::numeric_limits<double>::infinity();
    if (q >= 1.0) return 0.0;
    const double b = 1.0 - q;
    const double above = 25.0 / 3.0 * b * b * b;  // int_max(q,0.8)^1 25 (q'-1)^2
    if (q >= 0.8) return above;
    const double a = 0.8 / q;  // int_q^0.8 (0.8/q')^8 = (0.8/7) ((0.8/q)^7 - 1)
    const double a7 = a * a * a * a * a * a * a;
    return 25.0 / 3.0 * 0.008 + 0.8 / 7.0 * (a7 - 1.0);
  }

  /// Acceleration of fluid particle i due to boundary particle k, r_ik = r_i - r_k.
  Vec<D> acceleration(const Vec<D>& r_ik, const BoundaryParticles<D>& b, std::size_t k) const {
    const std::uint32_t first = b.normal_begin[k];
    const std::uint32_t last = b.normal_begin[k + 1];
    if (last - first == 1) return alongNormal(r_ik, b.normals[first]);
    // Corner: which of its normals is the fluid particle in front of?
    int in_front = 0;
    std::uint32_t only = first;
    for (std::uint32_t a = first; a < last; ++a) {
      if (r_ik.dot(b.normals[a]) > 0.0) {
        ++in_front;
        only = a;
      }
    }
    if (in_front == 0) return Vec<D>::Zero();
    if (in_front == 1) return alongNormal(r_ik, b.normals[only]);
    // Project r_ik on the span of the faced normals (Gram-Schmidt on at most D vectors).
    Vec<D> basis[D];
    int rank = 0;
    Vec<D> r_perp = Vec<D>::Zero();
    for (std::uint32_t a = first; a < last && rank < D; ++a) {
      if (r_ik.dot(b.normals[a]) <= 0.0) continue;
      Vec<D> e = b.normals[a];
      for (int c = 0; c < rank; ++c) e -= e.dot(basis[c]) * basis[c];
      const double len = e.norm();
      if (len < 1e-9) continue;
      basis[rank] = e / len;
      r_perp += r_ik.dot(basis[rank]) * basis[rank];
      ++rank;
    }
    const double dist = r_perp.norm();
    const double s = shape((dist + offset_) * inv_h_);
    if (s == 0.0 || dist == 0.0) return Vec<D>::Zero();
    const double par2 = (r_ik - r_perp).squaredNorm();
    if (par2 >= dx_ * dx_) return Vec<D>::Zero();
    const double par = std::sqrt(par2);
    const double B = 1.0 - par * inv_dx_;
    return (scale_ * B * s / dist) * r_perp + alongWall(r_ik - r_perp, par, dist);
  }

  /// How the face of a single-normal particle (normal n) meets a face of another
  /// particle of its surface (normal n2, the other particle at r_k - k_from_k2):
  /// SameFace (normals within 45 deg), Concave, Convex (k lies on the -t side of k2, t
  /// the part of n2 in k's plane) or Thin (back to back, k2 behind k's plane). Depends
  /// on the surface only, so Walls flags the particles near a Convex or Thin meeting once.
  enum class Meeting { SameFace, Concave, Convex, Thin };
  static Meeting meeting(const Vec<D>& n, const Vec<D>& n2, const Vec<D>& k_from_k2) {
    if (n2.dot(n) >= kOtherFace) return Meeting::SameFace;
    const Vec<D> t = n2 - n2.dot(n) * n;
    if (t.norm() < kOpposite) return k_from_k2.dot(n) > 0.0 ? Meeting::Thin : Meeting::Concave;
    return k_from_k2.dot(t) < 0.0 ? Meeting::Convex : Meeting::Concave;
  }

  /// Whether k's push on a fluid particle at r_ik (k has one normal) is cancelled by
  /// particle k2 at r_ik2 = r_i - r_k2 (see "Beyond an edge" above).
  bool beyondEdge(const Vec<D>& r_ik, std::size_t k, const Vec<D>& r_ik2, std::size_t k2,
                  const BoundaryParticles<D>& b) const {
    if (k2 == k || b.surface[k2] != b.surface[k]) return false;
    if (r_ik2.squaredNorm() >= 4.0 / (inv_h_ * inv_h_)) return false;
    const Vec<D>& n = b.normals[b.normal_begin[k]];
    const bool behind = r_ik.dot(n) < 0.0;
    for (std::uint32_t a = b.normal_begin[k2]; a < b.normal_begin[k2 + 1]; ++a) {
      const Vec<D>& n2 = b.normals[a];
      if (r_ik2.dot(n2) <= 0.0) continue;  // not in front of k2's face
      switch (meeting(n, n2, r_ik2 - r_ik)) {
        case Meeting::Thin:  // the fluid behind both faces of a thin part
          if (behind) return true;
          break;
        case Meeting::Convex:  // in front of k's plane the fluid must also be past k2 along t
          if (behind || r_ik2.dot(n2 - n2.dot(n) * n) > 0.0) return true;
          break;
        default:
          break;
      }
    }
    return false;
  }

 private:
  static constexpr double kOtherFace = 0.7071;  // cos 45 deg: the mesh sampler merges faces within 30 deg
  static constexpr double kOpposite = 0.1;      // |in-plane part| of n2 below which the faces are back to back
  // Behind the boundary particle's own plane (perp < 0) the push is held at its value
  // on the plane instead of rising to the singularity at perp = -b_off dx. A fluid
  // particle gets there only beside a body part thinner than b_off dx, where the far
  // face's particles would otherwise throw it through the body with unbounded force
  // (docs/validation/ship.md finding 1: 5e23 N on the ship). A flat wall's fluid does
  // not get there: the work of the push from q = 1 down to the plane is 0.01 c_s^2
  // times the integral of S from 0.417 to 1 (h = 1.2 dx), 0.11 c_s^2 per unit mass, so
  // a particle must arrive at 0.47 c_s, about five times the flow speed WCSPH allows.
  Vec<D> alongNormal(const Vec<D>& r_ik, const Vec<D>& n) const {
    const double perp = r_ik.dot(n);
    if (perp + offset_ <= 0.0) return Vec<D>::Zero();  // behind the offset wall
    const double s = shape((std::max(perp, 0.0) + offset_) * inv_h_);
    if (s == 0.0) return Vec<D>::Zero();
    const double par2 = r_ik.squaredNorm() - perp * perp;
    if (par2 >= dx_ * dx_) return Vec<D>::Zero();
    const double par = std::sqrt(std::max(par2, 0.0));
    const double B = 1.0 - par * inv_dx_;
    return (scale_ * B * s) * n + alongWall(r_ik - perp * n, par, perp);
  }

  /// The conservative form's part along the wall, -scale h Psi grad B, for the
  /// part r_par of r_ik along the wall (length par) at normal distance perp; zero for
  /// the reference form. Behind the plane (perp < 0) Psi continues linearly, matching
  /// the held push.
  Vec<D> alongWall(const Vec<D>& r_par, double par, double perp) const {
    if (!conservative_ || par < 1e-9 * dx_) return Vec<D>::Zero();
    const double q0 = offset_ * inv_h_;
    const double psi = perp >= 0.0 ? potential((perp + offset_) * inv_h_) : potential(q0) - shape(q0) * perp * inv_h_;
    return (scale_ * psi / (inv_h_ * dx_ * par)) * r_par;
  }

  double scale_;
  double inv_h_;
  double dx_;
  double inv_dx_;
  double offset_;
  bool conservative_;
};

}  // namespace moorsph::fluid
