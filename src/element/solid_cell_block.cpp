// The explicit block of solid cells (solid_cell_block.hpp): set-up, mass, stable step, results.
// The update is in solid_cell_block_kernel.cpp.
#include "abut/element/solid_cell_block.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "abut/core/error.hpp"
#include "abut/core/state_archive.hpp"
#include "abut/element/element_frequency.hpp"
#include "abut/element/lumped_mass.hpp"
#include "abut/material/mooney_rivlin.hpp"
#include "solid_cell_block_impl.hpp"

namespace abut {

std::string SolidCellBlock::Impl::element_name(std::size_t e) const {
  std::string name =
      "part " + std::to_string(part_id) + ", " + std::string(element_label(type)) + " element ";
  if (e < element_ids.size())
    name += std::to_string(element_ids[e]) + " (index " + std::to_string(e) + " in block)";
  else
    name += "index " + std::to_string(e) + " in block";
  return name;
}

void SolidCellBlock::Impl::gather(std::size_t e, const double* x, const double* y, const double* z,
                                  double* out) const {
  const std::int32_t* cell = &connectivity[e * static_cast<std::size_t>(nodes)];
  for (int a = 0; a < nodes; ++a) {
    const auto node = static_cast<std::size_t>(cell[a]);
    out[3 * a] = x[node];
    out[3 * a + 1] = y[node];
    out[3 * a + 2] = z[node];
  }
}

// V / (largest face area through the face's corners).
double SolidCellBlock::Impl::characteristic_length(const double* X, double volume) const {
  double largest = 0.0;
  for (const FaceTopology& f : topology(type).faces) {
    const auto p = [&](int k) {
      const int a = f.nodes[static_cast<std::size_t>(k)];
      return Vec3{X[3 * a], X[3 * a + 1], X[3 * a + 2]};
    };
    const Vec3 area = face_corner_count(f.type) == 3 ? cross(p(1) - p(0), p(2) - p(0))
                                                     : cross(p(2) - p(0), p(3) - p(1));
    largest = std::max(largest, 0.5 * norm(area));
  }
  return volume / largest;
}

SolidCellBlock::SolidCellBlock(std::int64_t part_id, const MaterialParams& material, CellType type,
                               std::vector<std::int32_t> connectivity, const Nodes& reference,
                               const FunctionTable* functions)
    : impl_(std::make_unique<Impl>()) {
  check_solid_material(part_id, material, functions);
  Impl& m = *impl_;
  m.part_id = part_id;
  m.material = material;
  m.functions = functions;
  m.type = type;
  m.nodes = topology(type).nodes;
  m.connectivity = std::move(connectivity);
  m.density = density_of(material);
  const ElasticModuli moduli = initial_moduli(material);
  const auto* rubber = std::get_if<MooneyRivlinParams>(&material);
  double viscous_shear = 0.0;  // as SolidBlock: the instantaneous stiffness of the viscous terms
  if (rubber) {
    for (int k = 0; k < 4; ++k) {
      if (rubber->beta[k] > 0.0)
        viscous_shear += rubber->alpha[k] / rubber->beta[k];
      else
        m.newtonian_viscosity += rubber->alpha[k];
    }
    m.viscous_terms = viscous_term_count(*rubber);
  }
  m.lame_mu = moduli.shear + viscous_shear;
  m.lame_lambda = moduli.bulk - 2.0 / 3.0 * m.lame_mu;
  m.wave_speed = std::sqrt((m.lame_lambda + 2.0 * m.lame_mu) / m.density);

  const std::span<const QuadraturePoint> rule = quadrature(type, Integration::full);
  m.points = static_cast<int>(rule.size());
  if (m.points > kMaxPoints) throw std::logic_error("SolidCellBlock: raise kMaxPoints");
  m.weight.resize(rule.size());
  m.natural.resize(3 * rule.size() * static_cast<std::size_t>(m.nodes));
  for (std::size_t q = 0; q < rule.size(); ++q) {
    double n[kMaxCellNodes];
    shape_functions(
        type, rule[q].xi, n,
        reinterpret_cast<double(*)[3]>(&m.natural[3 * q * static_cast<std::size_t>(m.nodes)]));
    m.weight[q] = rule[q].weight;
  }

  const auto nn = static_cast<std::size_t>(m.nodes), np = rule.size();
  if (m.connectivity.size() % nn != 0)
    throw InputError(input_prefix(part_id) + "the connectivity is not a whole number of cells");
  const std::size_t n = m.connectivity.size() / nn;
  m.shares.resize(n * nn);
  m.point_share.resize(n * np);
  m.length_factor.resize(n);
  m.reference_volume.resize(n);
  m.initial_step.resize(n);
  m.reference.resize(3 * nn * n);
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t a = 0; a < nn; ++a) {
      const std::int32_t node = m.connectivity[e * nn + a];
      if (node < 0 || static_cast<std::size_t>(node) >= reference.size())
        throw InputError(m.element_name(e) + ": node index " + std::to_string(node) +
                         " is outside the node list");
    }
  // The geometry of every element, in parallel (the element frequencies are the set-up's cost);
  // the first element with a non-positive Jacobian, in element order, is reported after.
  std::vector<std::int32_t> inverted_at(n, -1);  // the point, per element
  const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(dynamic, 64) if (count >= 64)
  for (std::int64_t k = 0; k < count; ++k) {
    const auto e = static_cast<std::size_t>(k);
    double X[3 * kMaxCellNodes];
    m.gather(e, reference.x.data(), reference.y.data(), reference.z.data(), X);
    const std::span<const double> coordinates(X, 3 * nn);
    double volume = 0.0;
    for (std::size_t q = 0; q < np && inverted_at[e] < 0; ++q) {
      double grad[kMaxCellNodes][3];
      const double det = natural_to_spatial(m.nodes, m.natural_at(q), X, grad);
      if (!(det > 0.0)) inverted_at[e] = static_cast<std::int32_t>(q);
      m.point_share[e * np + q] = m.weight[q] * det;
      volume += m.weight[q] * det;
    }
    if (inverted_at[e] >= 0) continue;
    for (std::size_t q = 0; q < np; ++q) m.point_share[e * np + q] /= volume;
    std::copy(X, X + 3 * nn, &m.reference[3 * nn * e]);
    m.reference_volume[e] = volume;
    lumped_volume_shares(type, coordinates, {&m.shares[e * nn], nn});
    m.initial_step[e] = cell_critical_step(type, coordinates, m.density, m.lame_lambda, m.lame_mu);
    // dt_e = factor l / c: the length that gives the eigenvalue's step, per unit of l.
    m.length_factor[e] = m.wave_speed * m.initial_step[e] / m.characteristic_length(X, volume);
  }
  for (std::size_t e = 0; e < n; ++e)
    if (inverted_at[e] >= 0)
      throw InputError(m.element_name(e) + ": Jacobian <= 0 at integration point " +
                       std::to_string(inverted_at[e] + 1) +
                       " in the initial configuration; expected the " +
                       std::string(topology(type).node_order));
  m.stress.assign(6 * np * n, 0.0);
  m.viscous.assign(6 * static_cast<std::size_t>(m.viscous_terms) * np * n, 0.0);
  if (const auto* metal = std::get_if<MetalParams>(&material)) {
    m.history.assign(np * n, {});
    m.fails_by_damage = metal->failure.active;
  }
  m.forces.assign(3 * nn * n, 0.0);
  m.internal_work.assign(n, 0.0);
  m.hourglass_work.assign(n, 0.0);
  m.bulk_pressure.assign(n, 0.0);
  m.stable.assign(n, 0.0);
  m.failure.assign(n, kOk);
  if (type == CellType::tet4) set_nodal_pressure(true);
}

void SolidCellBlock::set_nodal_pressure(bool on) {
  Impl& m = *impl_;
  if (on && m.type != CellType::tet4)
    throw InputError(input_prefix(m.part_id) + "the average nodal pressure is for C3D4 only, not " +
                     std::string(element_label(m.type)));
  m.nodal_pressure = on;
  m.local_node.clear();
  if (!on) return;
  std::vector<std::int32_t> numbers(m.connectivity.size());
  std::vector<std::int32_t> sorted = m.connectivity;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  for (std::size_t i = 0; i < m.connectivity.size(); ++i)
    numbers[i] = static_cast<std::int32_t>(
        std::lower_bound(sorted.begin(), sorted.end(), m.connectivity[i]) - sorted.begin());
  m.local_node = std::move(numbers);
  m.node_weight.assign(sorted.size(), 0.0);
  m.node_value.assign(sorted.size(), 0.0);
  m.element_weight.assign(m.size(), 0.0);
  m.element_value.assign(m.size(), 0.0);
}

bool SolidCellBlock::nodal_pressure() const { return impl_->nodal_pressure; }

SolidCellBlock::~SolidCellBlock() = default;
SolidCellBlock::SolidCellBlock(SolidCellBlock&&) noexcept = default;
SolidCellBlock& SolidCellBlock::operator=(SolidCellBlock&&) noexcept = default;

std::int64_t SolidCellBlock::part_id() const { return impl_->part_id; }
CellType SolidCellBlock::type() const { return impl_->type; }
std::size_t SolidCellBlock::size() const { return impl_->size(); }
int SolidCellBlock::nodes_per_element() const { return impl_->nodes; }
std::span<const std::int32_t> SolidCellBlock::element(std::size_t e) const {
  const auto nn = static_cast<std::size_t>(impl_->nodes);
  return {&impl_->connectivity[e * nn], nn};
}

void SolidCellBlock::add_lumped_mass(std::vector<double>& nodal_mass) const {
  const Impl& m = *impl_;
  for (std::size_t i = 0; i < m.connectivity.size(); ++i)
    nodal_mass[static_cast<std::size_t>(m.connectivity[i])] += m.density * m.shares[i];
}

double SolidCellBlock::initial_stable_step() const {
  double step = std::numeric_limits<double>::infinity();
  for (const double s : impl_->initial_step) step = std::min(step, s);
  return step;
}

const std::vector<double>& SolidCellBlock::element_forces() const { return impl_->forces; }

Sym3 SolidCellBlock::Impl::mean_stress(std::size_t e) const {
  Sym3 s;
  const auto np = static_cast<std::size_t>(points);
  for (std::size_t q = 0; q < np; ++q)
    for (int c = 0; c < 6; ++c) s[c] += point_share[e * np + q] * stress[6 * (e * np + q) + c];
  return s;
}

double SolidCellBlock::Impl::mean_history(std::size_t e, double PointHistory::*field) const {
  if (history.empty()) return 0.0;
  const auto np = static_cast<std::size_t>(points);
  double sum = 0.0;
  for (std::size_t q = 0; q < np; ++q) sum += point_share[e * np + q] * history[e * np + q].*field;
  return sum;
}

void SolidCellBlock::von_mises_stress(std::vector<double>& out) const {
  out.resize(size());
  for (std::size_t e = 0; e < size(); ++e) out[e] = von_mises(impl_->mean_stress(e));
}
void SolidCellBlock::pressure(std::vector<double>& out) const {
  out.resize(size());
  for (std::size_t e = 0; e < size(); ++e) out[e] = -trace(impl_->mean_stress(e)) / 3.0;
}
void SolidCellBlock::stress(std::vector<double>& out) const {
  out.resize(6 * size());
  for (std::size_t e = 0; e < size(); ++e) {
    const Sym3 s = impl_->mean_stress(e);
    std::copy(s.c.begin(), s.c.end(), &out[6 * e]);
  }
}
void SolidCellBlock::plastic_strain(std::vector<double>& out) const {
  out.resize(size());
  for (std::size_t e = 0; e < size(); ++e)
    out[e] = impl_->mean_history(e, &PointHistory::plastic_strain);
}
void SolidCellBlock::plastic_strain_rate(std::vector<double>& out) const {
  out.resize(size());
  for (std::size_t e = 0; e < size(); ++e)
    out[e] = impl_->mean_history(e, &PointHistory::plastic_strain_rate);
}
void SolidCellBlock::damage(std::vector<double>& out) const {
  out.resize(size());
  for (std::size_t e = 0; e < size(); ++e) out[e] = impl_->mean_history(e, &PointHistory::damage);
}

void SolidCellBlock::set_erosion(const ErosionCriteria& criteria) {
  set_block_erosion(*impl_, criteria, impl_->size());
}

const std::vector<std::uint8_t>& SolidCellBlock::eroded() const { return impl_->eroded; }

void SolidCellBlock::set_bulk_viscosity(double quadratic, double linear) {
  set_block_bulk_viscosity(*impl_, quadratic, linear);
}

void SolidCellBlock::set_thermal(const ThermalCoupling& coupling) {
  const Impl& m = *impl_;
  const auto* metal = std::get_if<MetalParams>(&m.material);
  const bool acts = coupling.expansion != 0.0 ||
                    (metal != nullptr && (coupling.plastic_work || metal->thermal()));
  if (acts)
    throw InputError(input_prefix(m.part_id) + "the coupling of " +
                     std::string(element_label(m.type)) +
                     " elements to the temperature is not supported yet (8-node hexahedra and "
                     "shells are coupled)");
}

void SolidCellBlock::set_element_ids(std::vector<std::int64_t> ids) {
  if (ids.size() != size())
    throw InputError(input_prefix(impl_->part_id) + "expected one element id per cell");
  impl_->element_ids = std::move(ids);
}

void SolidCellBlock::archive(StateArchive& a) {
  Impl& m = *impl_;
  a.mark("solid cell block");
  a.expect(m.part_id, "the part of a solid cell block");
  a.expect(static_cast<std::uint64_t>(m.size()), "the element count of a solid cell block");
  a.fixed(m.stress, m.viscous, m.history, m.forces, m.internal_work, m.hourglass_work,
          m.bulk_pressure, m.stable, m.failure, m.eroded, m.element_internal, m.element_hourglass,
          m.geometric_strain, m.volume_ratio);
  a.values(m.eroded_energy, m.eroded_count, m.internal_energy, m.hourglass_energy);
}

}  // namespace abut
