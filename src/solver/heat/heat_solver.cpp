// The temperature field: see heat.hpp. The solver's state is in heat_impl.hpp.
#include "abut/core/state_archive.hpp"
#include "heat_impl.hpp"

namespace abut {

HeatSolver::HeatSolver(const Model& model) : impl_(std::make_unique<Impl>(model)) {}
HeatSolver::~HeatSolver() = default;
HeatSolver::HeatSolver(HeatSolver&&) noexcept = default;
HeatSolver& HeatSolver::operator=(HeatSolver&&) noexcept = default;

bool HeatSolver::active() const { return impl_->block.has_value(); }
std::span<const double> HeatSolver::temperature() const { return impl_->t; }
std::span<const double> HeatSolver::capacity() const { return impl_->capacity; }
double HeatSolver::stable_step() const { return impl_->stable; }
void HeatSolver::advance(double t, double dt, std::span<const double> x, std::span<const double> y,
                         std::span<const double> z, std::span<const double> source) {
  impl_->advance(t, dt, x, y, z, source);
}
const HeatBalance& HeatSolver::balance() const { return impl_->balance; }
std::span<const double> HeatSolver::conduction_rate() const { return impl_->conduction; }

// The element flows of the conduction are recomputed at every step; the rest is fixed.
void HeatSolver::archive(StateArchive& a) {
  a.mark("heat");
  a.expect(static_cast<std::uint64_t>(impl_->t.size()), "the node count of the heat");
  a.fixed(impl_->t, impl_->rate, impl_->conduction);
  a.values(impl_->balance, impl_->stable);
}

}  // namespace abut
