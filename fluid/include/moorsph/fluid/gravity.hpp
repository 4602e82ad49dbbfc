#pragma once
// The "gravity" effect: a uniform body acceleration g (METHOD.md section 1, F_i).
#include <moorsph/fluid/counted.hpp>
#include <moorsph/fluid/fluid_effect.hpp>

namespace moorsph::fluid {

template <int D>
class Gravity final : public FluidEffect<D>, public Counted<Gravity<D>> {
 public:
  explicit Gravity(const Vec<D>& g) : g_(g) {}
  const char* name() const override { return "gravity"; }
  void addRates(FluidContext<D>& ctx) override {
    auto& a = ctx.fluid.dvdt;
    const std::size_t n = a.size();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) a[i] += g_;
  }
  const Vec<D>& acceleration() const { return g_; }

 private:
  Vec<D> g_;
};

}  // namespace moorsph::fluid
