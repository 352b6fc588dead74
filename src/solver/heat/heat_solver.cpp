// The temperature field: see heat.hpp. The solver's state is in heat_impl.hpp.
#include <algorithm>
#include <limits>

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
void HeatSolver::put_heat(std::span<const std::int32_t> nodes, std::span<const double> power,
                          double dt) {
  impl_->put_heat(nodes, power, dt);
}
void HeatSolver::hold(double t) { impl_->hold(t); }
void HeatSolver::plan(double t, double span, std::span<const double> x, std::span<const double> y,
                      std::span<const double> z, std::span<const double> exchange) {
  impl_->plan(t, span, x, y, z, exchange);
}
void HeatSolver::flow(double dt, std::span<const std::int32_t> nodes) { impl_->flow(dt, nodes); }
double HeatSolver::next_load_break(double t) const {
  const std::vector<double>& breaks = impl_->load_breaks;
  const auto next = std::upper_bound(breaks.begin(), breaks.end(), t);
  return next == breaks.end() ? std::numeric_limits<double>::infinity() : *next;
}
const HeatBalance& HeatSolver::balance() const { return impl_->balance; }
std::span<const double> HeatSolver::conduction_rate() const { return impl_->conduction; }

// The planned rates hold over a thermal step that a restart may fall within.
void HeatSolver::archive(StateArchive& a) {
  a.mark("heat");
  a.expect(static_cast<std::uint64_t>(impl_->t.size()), "the node count of the heat");
  a.fixed(impl_->t, impl_->rate, impl_->conduction, impl_->boundary_rate);
  a.values(impl_->balance, impl_->stable);
}

}  // namespace abut
