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
//  6. Stable step V / (largest face area) / c, c = sqrt((K + 4/3 G)/rho) from the initial moduli.
#include "abut/element/solid_block.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "abut/core/error.hpp"
#include "abut/element/hex8.hpp"
#include "abut/element/stable_step.hpp"
#include "abut/core/parallel.hpp"
#include "abut/material/elastic.hpp"
#include "abut/material/mooney_rivlin.hpp"
#include "abut/material/sym_tensor.hpp"

namespace abut {

namespace {

enum Failure : unsigned char { kOk = 0, kInverted = 1, kNonFinite = 2 };

struct ElasticLaw {
  LameConstants lame;
};

struct RubberLaw {
  const MooneyRivlinParams* params;
  ViscousStep viscous;  // factors for this step (count = number of active terms)
};

Sym3 add(const Sym3& a, const Sym3& b) {
  Sym3 s;
  for (int c = 0; c < 6; ++c) s[c] = a[c] + b[c];
  return s;
}

// Messages are built with append: GCC 12 reports a false -Wrestrict for "literal" + std::string&&.
std::string input_prefix(std::int64_t part_id) {
  std::string s("part ");
  s += std::to_string(part_id);
  s += ": ";
  return s;
}

void check_material(std::int64_t part_id, const MaterialParams& material) {
  const std::string where = input_prefix(part_id);
  if (is_rigid(material)) {
    throw InputError(where + "a rigid material cannot be used for a deformable solid block");
  }
  if (!(density_of(material) > 0.0)) throw InputError(where + "density must be > 0");
  if (const auto* e = std::get_if<ElasticParams>(&material)) {
    if (!(e->young > 0.0)) throw InputError(where + "Young's modulus must be > 0");
    if (!(e->poisson > -1.0 && e->poisson < 0.5)) {
      throw InputError(where + "Poisson's ratio must lie in (-1, 0.5)");
    }
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

}  // namespace

struct SolidBlock::Impl {
  std::int64_t part_id = 0;
  MaterialParams material;
  std::vector<Hex8> hexes;
  std::vector<std::int64_t> element_ids;
  double density = 0.0;
  double shear_modulus = 0.0;
  double wave_speed = 0.0;
  double hourglass_coefficient = kDefaultHourglassCoefficient;
  double bulk_viscosity_quadratic = kDefaultBulkViscosityQuadratic;
  double bulk_viscosity_linear = kDefaultBulkViscosityLinear;
  double newtonian_viscosity = 0.0;  // sum of alpha_k of the Mooney-Rivlin terms with beta_k = 0
  double lame_lambda = 0.0, lame_mu = 0.0;  // initial moduli for the stable step (mu with viscous terms)
  int viscous_terms = 0;

  std::vector<double> reference_volume;    // 1 per element
  std::vector<double> reference_gradient;  // Mooney-Rivlin only: B0 = b0/V0, 24 per element
  std::vector<double> stress;              // 6 per element (Sym3 order)
  std::vector<double> viscous;             // 6 per active viscous term per element
  std::vector<double> hourglass;           // generalized hourglass forces, 12 per element
  std::vector<double> forces;              // 24 per element
  std::vector<double> internal_work;       // per-element increments of the last step
  std::vector<double> hourglass_work;
  std::vector<double> stable;
  std::vector<unsigned char> failure;

  double internal_energy = 0.0;
  double hourglass_energy = 0.0;

  template <class Law>
  void element(std::size_t e, const NodalState& s, double dt, const Law& law);
  template <class Law>
  BlockStep step(const NodalState& s, double dt, const Law& law);
  std::string element_name(std::size_t e) const;
};

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

template <class Law>
void SolidBlock::Impl::element(std::size_t e, const NodalState& s, double dt, const Law& law) {
  const Hex8& hex = hexes[e];
  Hex8Coords cur;
  double v[3][8];
  for (int a = 0; a < 8; ++a) {
    const auto n = static_cast<std::size_t>(hex[a]);
    cur.x[a] = s.x[n];
    cur.y[a] = s.y[n];
    cur.z[a] = s.z[n];
    v[0][a] = s.vx[n];
    v[1][a] = s.vy[n];
    v[2][a] = s.vz[n];
  }
  Hex8Gradient g;
  hex8_gradient(cur, g);
  if (!(g.volume > 0.0)) {
    failure[e] = std::isfinite(g.volume) ? kInverted : kNonFinite;
    return;
  }

  // 1. Mid-step rates.
  Sym3 strain_increment;
  Mat3 rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};
  double mid_volume = g.volume;
  if (dt > 0.0) {
    Hex8Coords mid;
    for (int a = 0; a < 8; ++a) {
      mid.x[a] = cur.x[a] - 0.5 * dt * v[0][a];
      mid.y[a] = cur.y[a] - 0.5 * dt * v[1][a];
      mid.z[a] = cur.z[a] - 0.5 * dt * v[2][a];
    }
    Hex8Gradient gm;
    hex8_gradient(mid, gm);
    if (!(gm.volume > 0.0)) {
      failure[e] = std::isfinite(gm.volume) ? kInverted : kNonFinite;
      return;
    }
    mid_volume = gm.volume;
    double l[9] = {};  // velocity gradient times V_mid
    for (int a = 0; a < 8; ++a) {
      for (int i = 0; i < 3; ++i) {
        l[3 * i] += v[i][a] * gm.bx[a];
        l[3 * i + 1] += v[i][a] * gm.by[a];
        l[3 * i + 2] += v[i][a] * gm.bz[a];
      }
    }
    const double scale = dt / gm.volume;
    strain_increment = {{scale * l[0], scale * l[4], scale * l[8], 0.5 * scale * (l[1] + l[3]),
                         0.5 * scale * (l[5] + l[7]), 0.5 * scale * (l[6] + l[2])}};
    Mat3 half_spin;  // W dt / 2
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        half_spin[3 * i + j] = 0.25 * scale * (l[3 * i + j] - l[3 * j + i]);
    }
    rotation = cayley_rotation(half_spin);
  }

  // 2. Stress.
  double* stored = &stress[6 * e];
  const Sym3 old{{stored[0], stored[1], stored[2], stored[3], stored[4], stored[5]}};
  const Sym3 rotated = dt > 0.0 ? rotate(rotation, old) : old;
  Sym3 now;
  if constexpr (std::is_same_v<Law, ElasticLaw>) {
    now = dt > 0.0 ? add(rotated, hooke(law.lame, strain_increment)) : old;
  } else {
    const double* b0 = &reference_gradient[24 * e];
    const double* xs[3] = {cur.x, cur.y, cur.z};
    Mat3 f{};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        double sum = 0.0;
        for (int a = 0; a < 8; ++a) sum += xs[i][a] * b0[8 * j + a];
        f[3 * i + j] = sum;
      }
    }
    now = mooney_rivlin_stress(*law.params, f);
    const Sym3 dev_increment = deviator(strain_increment);
    double* history = &viscous[6 * static_cast<std::size_t>(viscous_terms) * e];
    for (int k = 0; k < viscous_terms; ++k) {
      double* hk = history + 6 * k;
      Sym3 h{{hk[0], hk[1], hk[2], hk[3], hk[4], hk[5]}};
      if (dt > 0.0) {
        const Sym3 hr = rotate(rotation, h);
        for (int c = 0; c < 6; ++c) {
          h[c] = law.viscous.decay[k] * hr[c] + law.viscous.gain[k] * dev_increment[c];
          hk[c] = h[c];
        }
      }
      now = add(now, h);
    }
  }
  for (int c = 0; c < 6; ++c) stored[c] = now[c];
  internal_work[e] =
      dt > 0.0 ? 0.5 * double_dot(add(rotated, now), strain_increment) * mid_volume : 0.0;

  // 3. Artificial bulk viscosity in compression (von Neumann-Richtmyer quadratic plus a linear
  // term, LS-DYNA Theory Manual, "Artificial Bulk Viscosity"): an extra pressure
  //   q = rho l (C0 l eps_v_dot^2 - C1 c eps_v_dot),  eps_v_dot < 0,  l = V^(1/3),
  // that spreads shock fronts over a few elements and damps the ringing behind them. It is not
  // part of the stored stress; its work goes to the internal energy.
  const double length = std::cbrt(g.volume);
  double bulk_q = 0.0, q_speed = 0.0;
  if (dt > 0.0) {
    const double volume_rate = (strain_increment[0] + strain_increment[1] + strain_increment[2]) / dt;
    if (volume_rate < 0.0) {
      q_speed = bulk_viscosity_linear * wave_speed - bulk_viscosity_quadratic * length * volume_rate;
      bulk_q = -density * length * q_speed * volume_rate;
      internal_work[e] += -bulk_q * volume_rate * dt * mid_volume;
    }
  }

  // 4. Hourglass forces.
  double gamma[4][8];
  hex8_hourglass_shape(g, gamma);
  double bb = 0.0;
  for (int a = 0; a < 8; ++a) bb += g.bx[a] * g.bx[a] + g.by[a] * g.by[a] + g.bz[a] * g.bz[a];
  const double stiffness = hourglass_coefficient * 2.0 * shear_modulus * bb / g.volume;
  double* q = &hourglass[12 * e];
  double work = 0.0;
  for (int alpha = 0; alpha < 4; ++alpha) {
    double rate[3];
    for (int i = 0; i < 3; ++i) {
      double sum = 0.0;
      for (int a = 0; a < 8; ++a) sum += v[i][a] * gamma[alpha][a];
      rate[i] = sum;
    }
    double* qa = q + 3 * alpha;
    double qr[3] = {qa[0], qa[1], qa[2]};
    if (dt > 0.0) {
      for (int i = 0; i < 3; ++i) {
        qr[i] = rotation[3 * i] * qa[0] + rotation[3 * i + 1] * qa[1] + rotation[3 * i + 2] * qa[2];
      }
    }
    for (int i = 0; i < 3; ++i) {
      qa[i] = qr[i] + stiffness * dt * rate[i];
      work += 0.5 * (qr[i] + qa[i]) * rate[i] * dt;
    }
  }
  hourglass_work[e] = work;

  // 5. Nodal forces (acting on the nodes).
  double* fe = &forces[24 * e];
  double check = 0.0;
  for (int a = 0; a < 8; ++a) {
    const double fx = (now[0] - bulk_q) * g.bx[a] + now[3] * g.by[a] + now[5] * g.bz[a];
    const double fy = now[3] * g.bx[a] + (now[1] - bulk_q) * g.by[a] + now[4] * g.bz[a];
    const double fz = now[5] * g.bx[a] + now[4] * g.by[a] + (now[2] - bulk_q) * g.bz[a];
    double h[3] = {0.0, 0.0, 0.0};
    for (int alpha = 0; alpha < 4; ++alpha) {
      for (int i = 0; i < 3; ++i) h[i] += q[3 * alpha + i] * gamma[alpha][a];
    }
    fe[3 * a] = -(fx + h[0]);
    fe[3 * a + 1] = -(fy + h[1]);
    fe[3 * a + 2] = -(fz + h[2]);
    check += std::abs(fe[3 * a]) + std::abs(fe[3 * a + 1]) + std::abs(fe[3 * a + 2]);
  }
  if (!std::isfinite(check + internal_work[e] + work)) {
    failure[e] = kNonFinite;
    return;
  }

  // 6. Stable step.
  // With bulk viscosity the step shrinks to l / (Q + sqrt(Q^2 + c^2)), Q = C1 c + C0 l |eps_v_dot|
  // (same manual, "Time Step Control"). A Newtonian viscosity eta adds its longitudinal part the
  // same way: 4/3 eta eps_dot = rho l Q_eta eps_dot, Q_eta = 4 eta / (3 rho l).
  const double l_char = hex8_critical_length(g, lame_lambda, lame_mu);
  const double q_total = q_speed + 4.0 * newtonian_viscosity / (3.0 * density * l_char);
  stable[e] = l_char / (q_total + std::sqrt(q_total * q_total + wave_speed * wave_speed));
  failure[e] = kOk;
}

template <class Law>
BlockStep SolidBlock::Impl::step(const NodalState& s, double dt, const Law& law) {
  const auto n = static_cast<std::int64_t>(hexes.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMinimum / 8)
  for (std::int64_t e = 0; e < n; ++e) element(static_cast<std::size_t>(e), s, dt, law);

  // Serial pass in element order: the first failure decides the message, sums are in a fixed
  // order, so the result does not depend on the number of threads.
  BlockStep out;
  out.stable_step = std::numeric_limits<double>::infinity();
  double internal = 0.0, hourglass_sum = 0.0;
  for (std::size_t e = 0; e < hexes.size(); ++e) {
    if (failure[e] == kInverted) {
      throw InstabilityError(element_name(e) + ": inverted element (volume <= 0)");
    }
    if (failure[e] == kNonFinite) {
      throw InstabilityError(element_name(e) + ": non-finite volume, stress or force");
    }
    internal += internal_work[e];
    hourglass_sum += hourglass_work[e];
    out.stable_step = std::min(out.stable_step, stable[e]);
  }
  internal_energy += internal;
  hourglass_energy += hourglass_sum;
  out.internal_energy = internal_energy;
  out.hourglass_energy = hourglass_energy;
  return out;
}

SolidBlock::SolidBlock(std::int64_t part_id, const MaterialParams& material,
                       std::vector<Hex8> hexes, const Nodes& reference)
    : impl_(std::make_unique<Impl>()) {
  check_material(part_id, material);
  Impl& m = *impl_;
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
      if (rubber->beta[k] > 0.0) viscous_shear += rubber->alpha[k] / rubber->beta[k];
      else m.newtonian_viscosity += rubber->alpha[k];
    }
  }
  m.lame_mu = moduli.shear + viscous_shear;
  m.lame_lambda = moduli.bulk - 2.0 / 3.0 * m.lame_mu;
  m.wave_speed = std::sqrt((m.lame_lambda + 2.0 * m.lame_mu) / m.density);
  m.viscous_terms = rubber ? viscous_term_count(*rubber) : 0;

  const std::size_t n = m.hexes.size();
  m.reference_volume.resize(n);
  if (rubber) m.reference_gradient.resize(24 * n);
  for (std::size_t e = 0; e < n; ++e) {
    Hex8Coords x;
    for (int a = 0; a < 8; ++a) {
      const std::int32_t node = m.hexes[e][a];
      if (node < 0 || static_cast<std::size_t>(node) >= reference.size()) {
        std::string message = m.element_name(e);
        message += ": node index ";
        message += std::to_string(node);
        message += " is outside the node list";
        throw InputError(message);
      }
      x.x[a] = reference.x[node];
      x.y[a] = reference.y[node];
      x.z[a] = reference.z[node];
    }
    Hex8Gradient g;
    hex8_gradient(x, g);
    if (!(g.volume > 0.0)) {
      throw InputError(m.element_name(e) +
                       ": volume <= 0 in the initial configuration; expected nodes 1-4 "
                       "counter-clockwise on the bottom face seen from above, 5-8 above them");
    }
    m.reference_volume[e] = g.volume;
    if (rubber) {
      double* b0 = &m.reference_gradient[24 * e];
      for (int a = 0; a < 8; ++a) {
        b0[a] = g.bx[a] / g.volume;
        b0[8 + a] = g.by[a] / g.volume;
        b0[16 + a] = g.bz[a] / g.volume;
      }
    }
  }
  m.stress.assign(6 * n, 0.0);
  m.viscous.assign(6 * static_cast<std::size_t>(m.viscous_terms) * n, 0.0);
  m.hourglass.assign(12 * n, 0.0);
  m.forces.assign(24 * n, 0.0);
  m.internal_work.assign(n, 0.0);
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
  for (std::size_t e = 0; e < impl_->hexes.size(); ++e) {
    Hex8Coords x;
    for (int a = 0; a < 8; ++a) {
      const auto node = static_cast<std::size_t>(impl_->hexes[e][a]);
      x.x[a] = reference.x[node];
      x.y[a] = reference.y[node];
      x.z[a] = reference.z[node];
    }
    Hex8Gradient g;
    hex8_gradient(x, g);
    const double length = hex8_critical_length(g, impl_->lame_lambda, impl_->lame_mu);
    const double q = 4.0 * impl_->newtonian_viscosity / (3.0 * impl_->density * length);
    step = std::min(step, length / (q + std::sqrt(q * q + impl_->wave_speed * impl_->wave_speed)));
  }
  return step;
}

BlockStep SolidBlock::update(const NodalState& state, double dt) {
  if (!(dt >= 0.0) || !std::isfinite(dt)) {
    throw InstabilityError(input_prefix(impl_->part_id) + "time step must be finite and >= 0");
  }
  Impl& m = *impl_;
  if (const auto* e = std::get_if<ElasticParams>(&m.material)) {
    return m.step(state, dt, ElasticLaw{lame_constants(*e)});
  }
  const auto& rubber = std::get<MooneyRivlinParams>(m.material);
  return m.step(state, dt, RubberLaw{&rubber, dt > 0.0 ? viscous_step(rubber, dt) : ViscousStep{}});
}

const std::vector<double>& SolidBlock::element_forces() const { return impl_->forces; }

void SolidBlock::von_mises_stress(std::vector<double>& out) const {
  out.resize(size());
  for (std::size_t e = 0; e < size(); ++e) {
    const double* s = &impl_->stress[6 * e];
    out[e] = von_mises(Sym3{{s[0], s[1], s[2], s[3], s[4], s[5]}});
  }
}

void SolidBlock::pressure(std::vector<double>& out) const {
  out.resize(size());
  for (std::size_t e = 0; e < size(); ++e) {
    const double* s = &impl_->stress[6 * e];
    out[e] = -(s[0] + s[1] + s[2]) / 3.0;
  }
}

void SolidBlock::stress(std::vector<double>& out) const { out = impl_->stress; }

void SolidBlock::set_hourglass_coefficient(double coefficient) {
  if (!(coefficient >= 0.0) || !std::isfinite(coefficient)) {
    throw InputError(input_prefix(impl_->part_id) + "hourglass coefficient must be >= 0");
  }
  impl_->hourglass_coefficient = coefficient;
}

double SolidBlock::hourglass_coefficient() const { return impl_->hourglass_coefficient; }

void SolidBlock::set_bulk_viscosity(double quadratic, double linear) {
  if (!(quadratic >= 0.0) || !(linear >= 0.0))
    throw InputError("bulk viscosity coefficients must be >= 0");
  impl_->bulk_viscosity_quadratic = quadratic;
  impl_->bulk_viscosity_linear = linear;
}

void SolidBlock::set_element_ids(std::vector<std::int64_t> ids) {
  if (ids.size() != size()) {
    throw InputError(input_prefix(impl_->part_id) + "expected one element id per hexahedron");
  }
  impl_->element_ids = std::move(ids);
}

}  // namespace abut
