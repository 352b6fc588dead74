// One-point hexahedra with Flanagan-Belytschko hourglass control (FB81 = Flanagan and
// Belytschko 1981, IJNME 17:679-706) and an objective stress update.
//
// Per element and step (contract in solid_block.hpp):
//  1. Rates at the mid-step configuration x^{n-1/2} = x^n - dt/2 v^{n-1/2}: velocity gradient
//     L = sum_a v_a (x) b_a / V, strain increment D dt = sym(L) dt, spin W = skew(L). For a rigid
//     rotation the mid-step gradient is exactly skew (Cayley transform), so no spurious strain.
//  2. Stress: rotate with the Hughes-Winget increment Q = cayley(W dt/2) (Hughes and Winget
//     1980, IJNME 15:1862), then
//       ElasticParams: add Hooke's law of D dt (hypoelastic, Jaumann-type rate);
//       MooneyRivlinParams: elastic stress from F = sum_a x_a (x) B0_a with the mean gradient B0
//       of the reference configuration (total Lagrangian at the centroid), plus the rotated and
//       recursively updated viscous stresses (mooney_rivlin.hpp).
//     Coupled to the temperature (ThermalCoupling, issue 11), the hypoelastic laws take the
//     mechanical increment D dt - alpha dT I and flow at the element temperature.
//  3. Internal energy increment V_mid (sigma_rot + sigma_new)/2 : D dt (trapezoidal rule).
//  4. Hourglass (FB81 stiffness form): generalized hourglass rates qdot_alpha = sum_a v_a
//     gamma_alpha(a) with the gamma vectors at x^n, generalized forces updated incrementally,
//     Q_alpha <- R Q_alpha + k qdot_alpha dt (rotated with the same R, so a rigid rotation
//     carries them along), with stiffness k = c_hg 2 G (b:b) / V. The scaling modulus * b:b / V
//     follows FB81's hourglass stiffness; we use the shear modulus 2G rather than the
//     dilatational lambda + 2 mu because hourglass (bending-like) modes are shear-dominated and
//     the dilatational modulus would lock nearly incompressible rubber (Belytschko and Bindeman
//     1993, CMAME 105:225). c_hg defaults to 0.05 (kDefaultHourglassCoefficient); for a cube of
//     side h, k = 3 c_hg G h, while the mode's physical stiffness is of order G h.
//     Hourglass work: (Q_rot + Q_new)/2 . qdot dt, which is the work of the nodal hourglass forces.
//  5. Nodal forces at x^n: f_a = -(sigma b_a + sum_alpha Q_alpha gamma_alpha(a)).
//  6. Stable step: the one-point hexahedron's bound of stable_step.hpp with the initial moduli,
//     shortened by the bulk viscosity.
//
// Evaluation (solid_block_kernel.cpp): the kernel works in the modal (Walsh) form of hex8.hpp.
// Positions and velocities are transformed once; the mid-step modes are c - dt/2 w; all sums over
// nodes (sum_a v_a (x) b_a, F, b:b, the hourglass rates) are sums over the six modes with a nonzero
// gradient, and the nodal forces are one transform back. This is the same algebra as the nodal form
// (identical up to round-off) with one geometry evaluation per configuration and no b_a or gamma
// arrays.
#include "abut/element/solid_block.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "abut/core/error.hpp"
#include "abut/core/parallel.hpp"
#include "abut/core/state_archive.hpp"
#include "abut/element/hex8.hpp"
#include "abut/element/stable_step.hpp"
#include "abut/material/elastic.hpp"
#include "abut/material/metal.hpp"
#include "abut/material/mooney_rivlin.hpp"
#include "abut/material/point_law.hpp"
#include "abut/material/sym_tensor.hpp"
#include "solid_block_impl.hpp"

namespace abut {

void check_solid_material(std::int64_t part_id, const MaterialParams& material,
                          const FunctionTable* functions) {
  const std::string where = input_prefix(part_id);
  if (is_rigid(material)) {
    throw InputError(where + "a rigid material cannot be used for a deformable solid block");
  }
  if (!(density_of(material) > 0.0)) throw InputError(where + "density must be > 0");
  auto check_isotropic = [&](double young, double poisson) {
    if (!(young > 0.0)) throw InputError(where + "Young's modulus must be > 0");
    if (!(poisson > -1.0 && poisson < 0.5))
      throw InputError(where + "Poisson's ratio must lie in (-1, 0.5)");
  };
  if (const auto* e = std::get_if<ElasticParams>(&material)) check_isotropic(e->young, e->poisson);
  if (const auto* m = std::get_if<MetalParams>(&material)) {
    check_isotropic(m->young, m->poisson);
    if (!m->johnson_cook && !(functions && m->flow_curve.valid()))
      throw InputError(where + "the flow stress curve of *MAT_METAL is missing");
  }
  if (const auto* m = std::get_if<MooneyRivlinParams>(&material)) {
    if (!(m->bulk > 0.0)) throw InputError(where + "bulk modulus K must be > 0");
    if (!(m->c1 + m->c2 >= 0.0)) throw InputError(where + "C1 + C2 must be >= 0");
    for (std::size_t k = 0; k < m->alpha.size(); ++k) {
      if (!(m->alpha[k] >= 0.0) || !(m->beta[k] >= 0.0)) {
        throw InputError(where + "viscous parameters alpha_k and beta_k must be >= 0");
      }
    }
  }
}

std::string SolidBlock::Impl::element_name(std::size_t e) const {
  std::string name("part ");
  name += std::to_string(part_id);
  name += ", element ";
  if (e < element_ids.size()) {
    name += std::to_string(element_ids[e]);
    name += " (index ";
    name += std::to_string(e);
    name += " in block)";
  } else {
    name += "index ";
    name += std::to_string(e);
    name += " in block";
  }
  return name;
}

SolidBlock::SolidBlock(std::int64_t part_id, const MaterialParams& material,
                       std::vector<Hex8> hexes, const Nodes& reference,
                       const FunctionTable* functions)
    : impl_(std::make_unique<Impl>()) {
  check_solid_material(part_id, material, functions);
  Impl& m = *impl_;
  m.functions = functions;
  m.part_id = part_id;
  m.material = material;
  m.hexes = std::move(hexes);
  m.density = density_of(material);
  const ElasticModuli moduli = initial_moduli(material);
  m.shear_modulus = moduli.shear;
  const auto* rubber = std::get_if<MooneyRivlinParams>(&material);
  // Viscous terms stiffen the element for stability: a term with relaxation time beta_k acts at
  // most like an extra shear modulus alpha_k / beta_k (its instantaneous response), a Newtonian
  // term (beta_k = 0) like a viscosity alpha_k, which enters the step as Q below.
  double viscous_shear = 0.0;
  if (rubber) {
    for (int k = 0; k < 4; ++k) {
      if (rubber->beta[k] > 0.0)
        viscous_shear += rubber->alpha[k] / rubber->beta[k];
      else
        m.newtonian_viscosity += rubber->alpha[k];
    }
  }
  m.lame_mu = moduli.shear + viscous_shear;
  m.lame_lambda = moduli.bulk - 2.0 / 3.0 * m.lame_mu;
  m.wave_speed = std::sqrt((m.lame_lambda + 2.0 * m.lame_mu) / m.density);
  m.viscous_terms = rubber ? viscous_term_count(*rubber) : 0;

  const std::size_t n = m.hexes.size();
  m.reference_volume.resize(n);
  m.reference_gradient.resize(Impl::kReferenceModes * n);  // hyperelasticity, erosion strain
  for (std::size_t e = 0; e < n; ++e) {
    for (const std::int32_t node : m.hexes[e]) {
      if (node < 0 || static_cast<std::size_t>(node) >= reference.size()) {
        std::string message = m.element_name(e);
        message += ": node index ";
        message += std::to_string(node);
        message += " is outside the node list";
        throw InputError(message);
      }
    }
    const Hex8ModalGradient g = hex8_modal_gradient_at(m.hexes[e], reference);
    if (!(g.volume > 0.0)) {
      throw InputError(m.element_name(e) +
                       ": volume <= 0 in the initial configuration; expected nodes 1-4 "
                       "counter-clockwise on the bottom face seen from above, 5-8 above them");
    }
    m.reference_volume[e] = g.volume;
    {
      double* r0 = &m.reference_gradient[Impl::kReferenceModes * e];
      for (int k = 1; k < 7; ++k) {
        r0[k - 1] = 8.0 * g.gx[k] / g.volume;
        r0[6 + k - 1] = 8.0 * g.gy[k] / g.volume;
        r0[12 + k - 1] = 8.0 * g.gz[k] / g.volume;
      }
    }
  }
  m.stress.assign(Impl::batched_size(n, 6), 0.0);
  m.viscous.assign(6 * static_cast<std::size_t>(m.viscous_terms) * n, 0.0);
  m.hourglass.assign(Impl::batched_size(n, 12), 0.0);
  m.forces.assign(24 * n, 0.0);
  m.internal_work.assign(n, 0.0);
  m.bulk_pressure.assign(n, 0.0);
  if (const auto* metal = std::get_if<MetalParams>(&material)) {
    m.history.assign(n, {});
    m.fails_by_damage = metal->failure.active;
  }
  m.hourglass_work.assign(n, 0.0);
  m.stable.assign(n, 0.0);
  m.failure.assign(n, kOk);
}

SolidBlock::~SolidBlock() = default;
SolidBlock::SolidBlock(SolidBlock&&) noexcept = default;
SolidBlock& SolidBlock::operator=(SolidBlock&&) noexcept = default;

std::int64_t SolidBlock::part_id() const { return impl_->part_id; }
const std::vector<Hex8>& SolidBlock::hexes() const { return impl_->hexes; }
std::size_t SolidBlock::size() const { return impl_->hexes.size(); }

void SolidBlock::add_lumped_mass(std::vector<double>& nodal_mass) const {
  for (std::size_t e = 0; e < impl_->hexes.size(); ++e) {
    const double share = impl_->density * impl_->reference_volume[e] / 8.0;
    for (std::int32_t node : impl_->hexes[e]) nodal_mass[static_cast<std::size_t>(node)] += share;
  }
}

double SolidBlock::initial_stable_step(const Nodes& reference) const {
  double step = std::numeric_limits<double>::infinity();
  for (const Hex8& hex : impl_->hexes) {
    const double length = hex8_critical_length(hex8_modal_gradient_at(hex, reference),
                                               impl_->lame_lambda, impl_->lame_mu);
    step = std::min(step, impl_->critical_step(length, 0.0));
  }
  return step;
}

const std::vector<double>& SolidBlock::element_forces() const { return impl_->forces; }

void SolidBlock::von_mises_stress(std::vector<double>& out) const {
  out.resize(size());
  for (std::size_t e = 0; e < size(); ++e) out[e] = von_mises(impl_->element_stress(e));
}

void SolidBlock::set_erosion(const ErosionCriteria& criteria) {
  set_block_erosion(*impl_, criteria, impl_->hexes.size());
}

const std::vector<std::uint8_t>& SolidBlock::eroded() const { return impl_->eroded; }

void SolidBlock::plastic_strain(std::vector<double>& out) const {
  out.assign(size(), 0.0);
  for (std::size_t e = 0; e < impl_->history.size(); ++e) out[e] = impl_->history[e].plastic_strain;
}

void SolidBlock::plastic_strain_rate(std::vector<double>& out) const {
  out.assign(size(), 0.0);
  for (std::size_t e = 0; e < impl_->history.size(); ++e)
    out[e] = impl_->history[e].plastic_strain_rate;
}

void SolidBlock::damage(std::vector<double>& out) const {
  out.assign(size(), 0.0);
  for (std::size_t e = 0; e < impl_->history.size(); ++e) out[e] = impl_->history[e].damage;
}

void SolidBlock::pressure(std::vector<double>& out) const {
  out.resize(size());
  for (std::size_t e = 0; e < size(); ++e) {
    const Sym3 s = impl_->element_stress(e);
    out[e] = -(s[0] + s[1] + s[2]) / 3.0;
  }
}

void SolidBlock::stress(std::vector<double>& out) const {
  out.resize(6 * size());
  for (std::size_t e = 0; e < size(); ++e) {
    const Sym3 s = impl_->element_stress(e);
    std::copy(s.c.begin(), s.c.end(), &out[6 * e]);
  }
}

void SolidBlock::set_hourglass_coefficient(double coefficient) {
  if (!(coefficient >= 0.0) || !std::isfinite(coefficient)) {
    throw InputError(input_prefix(impl_->part_id) + "hourglass coefficient must be >= 0");
  }
  impl_->hourglass_coefficient = coefficient;
}

double SolidBlock::hourglass_coefficient() const { return impl_->hourglass_coefficient; }

void SolidBlock::set_bulk_viscosity(double quadratic, double linear) {
  set_block_bulk_viscosity(*impl_, quadratic, linear);
}

void SolidBlock::set_thermal(const ThermalCoupling& coupling) {
  Impl& m = *impl_;
  const auto* metal = std::get_if<MetalParams>(&m.material);
  const bool plastic = metal != nullptr && coupling.plastic_work;
  const bool softens = metal != nullptr && metal->thermal();  // softening or d5
  if (coupling.expansion != 0.0 && std::holds_alternative<MooneyRivlinParams>(m.material))
    throw InputError(input_prefix(m.part_id) +
                     "thermal expansion of *MAT_MOONEY_RIVLIN is not supported yet");
  if (!std::isfinite(coupling.expansion))
    throw InputError(input_prefix(m.part_id) + "thermal expansion must be finite");
  m.coupling = coupling;
  m.coupled = coupling.expansion != 0.0 || plastic || softens;
  m.temperature_started = false;
  m.element_temperature.assign(m.coupled ? m.hexes.size() : 0, 0.0);
  m.element_thermal_work.assign(m.coupled ? m.hexes.size() : 0, 0.0);
  m.element_plastic_work.assign(plastic ? m.hexes.size() : 0, 0.0);
}

bool SolidBlock::thermal() const { return impl_->coupled; }

const std::vector<double>& SolidBlock::plastic_work() const { return impl_->element_plastic_work; }

// Everything update() carries from one step to the next; the geometry, material and element
// ids come from the model.
void SolidBlock::archive(StateArchive& a) {
  Impl& m = *impl_;
  a.mark("solid block");
  a.expect(m.part_id, "the part of a solid block");
  a.expect(static_cast<std::uint64_t>(m.hexes.size()), "the element count of a solid block");
  a.expect(static_cast<std::uint64_t>(kLanes),
           "the SIMD width of the build (the elements' state is kept in batches of that many)");
  a.fixed(m.stress, m.viscous, m.hourglass, m.forces, m.internal_work, m.bulk_pressure, m.history,
          m.eroded, m.element_internal, m.element_hourglass, m.geometric_strain, m.volume_ratio,
          m.hourglass_work, m.stable, m.failure, m.element_temperature, m.element_plastic_work,
          m.element_thermal_work);
  a.values(m.eroded_energy, m.eroded_count, m.internal_energy, m.hourglass_energy,
           m.temperature_started, m.thermal_work);
}

void SolidBlock::set_element_ids(std::vector<std::int64_t> ids) {
  if (ids.size() != size()) {
    throw InputError(input_prefix(impl_->part_id) + "expected one element id per hexahedron");
  }
  impl_->element_ids = std::move(ids);
}

}  // namespace abut
