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
//  6. Stable step V / (largest face area) / c, c = sqrt((K + 4/3 G)/rho) from the initial moduli.
//
// Evaluation: the kernel works in the modal (Walsh) form of hex8.hpp. Positions and velocities
// are transformed once; the mid-step modes are c - dt/2 w; all sums over nodes (sum_a v_a (x) b_a,
// F, b:b, the hourglass rates) are sums over the six modes with a nonzero gradient, and the
// nodal forces are one transform back. This is the same algebra as the nodal form (identical up
// to round-off) with one geometry evaluation per configuration and no b_a or gamma arrays.
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

namespace abut {

namespace {

enum Failure : unsigned char { kOk = 0, kInverted = 1, kNonFinite = 2 };

struct RubberLaw {
  const MooneyRivlinParams* params;
  ViscousStep viscous;  // factors for this step (count = number of active terms)
};

// sum_a u_a (x) b_a = 8 sum_k u_k (x) G_k (hex8.hpp), row-major: l[3 i + j] = sum_a u_ai b_aj.
void gradient_times_volume(const Hex8Modes& u, const Hex8ModalGradient& g, double l[9]) {
  const double* us[3] = {u.x, u.y, u.z};
  for (int i = 0; i < 3; ++i) {
    double sx = 0.0, sy = 0.0, sz = 0.0;
    for (int k = 1; k < 7; ++k) {  // G_0 = G_7 = 0
      sx += us[i][k] * g.gx[k];
      sy += us[i][k] * g.gy[k];
      sz += us[i][k] * g.gz[k];
    }
    l[3 * i] = 8.0 * sx;
    l[3 * i + 1] = 8.0 * sy;
    l[3 * i + 2] = 8.0 * sz;
  }
}

// Messages are built with append: GCC 12 reports a false -Wrestrict for "literal" + std::string&&.
std::string input_prefix(std::int64_t part_id) {
  std::string s("part ");
  s += std::to_string(part_id);
  s += ": ";
  return s;
}

void check_material(std::int64_t part_id, const MaterialParams& material,
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

// Effective deviatoric logarithmic strain sqrt(2/3 e_dev:e_dev) of F = sum_k c_k (x) R_k
// (R_k = 8 G0_k / V0, hex8.hpp), from the eigenvalues of C = F^T F: e_i = ln(lambda_i) / 2.
double deviatoric_log_strain(const Hex8Modes& c, const double* r0) {
  const double* cs[3] = {c.x, c.y, c.z};
  Mat3 f{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double sum = 0.0;
      for (int k = 1; k < 7; ++k) sum += cs[i][k] * r0[6 * j + k - 1];
      f[3 * i + j] = sum;
    }
  Sym3 right_cauchy_green;
  const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
  for (int q = 0; q < 6; ++q) {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) sum += f[3 * k + pairs[q][0]] * f[3 * k + pairs[q][1]];
    right_cauchy_green[q] = sum;
  }
  const SymEigen eig = eigen_symmetric(right_cauchy_green);
  double e[3], mean = 0.0;
  for (int i = 0; i < 3; ++i) {
    e[i] = 0.5 * std::log(eig.values[static_cast<std::size_t>(i)]);
    mean += e[i] / 3.0;
  }
  double sum = 0.0;
  for (double v : e) sum += (v - mean) * (v - mean);
  return std::sqrt(2.0 / 3.0 * sum);
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
  double lame_lambda = 0.0,
         lame_mu = 0.0;  // initial moduli for the stable step (mu with viscous terms)
  int viscous_terms = 0;

  std::vector<double> reference_volume;  // 1 per element
  // Mooney-Rivlin only: R_k = 8 G0_k / V0 of the reference configuration for the modes k = 1..6,
  // stored per element as R[6 j + k - 1] (component j), so that F = sum_k c_k (x) R_k.
  static constexpr std::size_t kReferenceModes = 18;
  std::vector<double> reference_gradient;
  std::vector<double> stress;         // 6 per element (Sym3 order)
  std::vector<double> viscous;        // 6 per active viscous term per element
  std::vector<double> hourglass;      // generalized hourglass forces, 12 per element
  std::vector<double> forces;         // 24 per element
  std::vector<double> internal_work;  // per-element increments of the last step
  std::vector<PointHistory> history;  // plastic strain and damage (metals)
  bool fails_by_damage = false;       // a metal with a damage property: erodes at D >= 1
  ErosionCriteria erosion;
  std::vector<std::uint8_t> eroded;
  std::vector<double> element_internal, element_hourglass;  // cumulative work per element (erosion)
  std::vector<double> geometric_strain, volume_ratio;       // erosion measures at the last update
  double eroded_energy = 0.0;
  std::size_t eroded_count = 0;
  const FunctionTable* functions = nullptr;  // flow curves of *MAT_METAL
  std::vector<double> hourglass_work;
  std::vector<double> stable;
  std::vector<unsigned char> failure;

  double internal_energy = 0.0;
  double hourglass_energy = 0.0;

  // Coupling to the temperature (issue 11; solid_block.hpp): off unless set_thermal made it on.
  ThermalCoupling coupling;
  bool coupled = false;
  bool temperature_started = false;          // element_temperature holds the last temperatures
  std::vector<double> element_temperature;   // at the last update, 1 per element (coupled)
  std::vector<double> element_plastic_work;  // of the last step (coupling.plastic_work)

  // kThermal: the block is coupled (decided once per block and step, so that the uncoupled
  // kernel is unchanged).
  template <class Law, bool kThermal>
  void element(std::size_t e, const NodalState& s, double dt, const Law& law);
  template <class Law, bool kThermal = false>
  BlockStep step(const NodalState& s, double dt, const Law& law);
  void erode(BlockStep& out);
  std::string element_name(std::size_t e) const;
  // l / (Q + sqrt(Q^2 + c^2)) with Q = q_speed (bulk viscosity) plus the Newtonian Q_eta.
  double critical_step(double length, double q_speed) const {
    const double q = q_speed + 4.0 * newtonian_viscosity / (3.0 * density * length);
    return length / (q + std::sqrt(q * q + wave_speed * wave_speed));
  }
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

template <class Law, bool kThermal>
void SolidBlock::Impl::element(std::size_t e, const NodalState& s, double dt, const Law& law) {
  // Gather the nodal data once and go to the modal form (hex8.hpp): every per-node sum below
  // (velocity gradients, F, hourglass rates, b:b) becomes a sum over the six modes with G_k != 0.
  if (!eroded.empty() && eroded[e]) {
    std::fill_n(&forces[24 * e], 24, 0.0);
    internal_work[e] = hourglass_work[e] = 0.0;
    if (!element_plastic_work.empty()) element_plastic_work[e] = 0.0;
    stable[e] = std::numeric_limits<double>::infinity();
    failure[e] = kOk;
    return;
  }
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
  Hex8Modes c, w;  // modes of x^n and of v^{n-1/2}
  hex8_to_modes(cur.x, c.x);
  hex8_to_modes(cur.y, c.y);
  hex8_to_modes(cur.z, c.z);
  hex8_to_modes(v[0], w.x);
  hex8_to_modes(v[1], w.y);
  hex8_to_modes(v[2], w.z);
  Hex8ModalGradient g;
  hex8_modal_gradient(c, g);
  if (!(g.volume > 0.0)) {
    failure[e] = std::isfinite(g.volume) ? kInverted : kNonFinite;
    return;
  }

  // 1. Mid-step rates. The transform is linear, so the modes of x^{n-1/2} are c - dt/2 w.
  Sym3 strain_increment;
  Mat3 rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};
  double mid_volume = g.volume;
  if (dt > 0.0) {
    Hex8Modes mid;
    for (int k = 0; k < 8; ++k) {
      mid.x[k] = c.x[k] - 0.5 * dt * w.x[k];
      mid.y[k] = c.y[k] - 0.5 * dt * w.y[k];
      mid.z[k] = c.z[k] - 0.5 * dt * w.z[k];
    }
    Hex8ModalGradient gm;
    hex8_modal_gradient(mid, gm);
    if (!(gm.volume > 0.0)) {
      failure[e] = std::isfinite(gm.volume) ? kInverted : kNonFinite;
      return;
    }
    mid_volume = gm.volume;
    double l[9];  // velocity gradient times V_mid
    gradient_times_volume(w, gm, l);
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
  if constexpr (kThermal) {  // hypoelastic point laws coupled to the temperature
    // The element temperature, and the thermal strain increment alpha dT I of its change since
    // the last update taken out of the total increment (the mechanical strain drives the law).
    double temperature = 0.0;
    for (int a = 0; a < 8; ++a) temperature += s.temperature[static_cast<std::size_t>(hex[a])];
    temperature *= 0.125;
    double& last = element_temperature[e];
    const double change = temperature_started ? temperature - last : 0.0;
    last = temperature;
    now = old;
    if (!element_plastic_work.empty()) element_plastic_work[e] = 0.0;
    if (dt > 0.0) {
      Sym3 mechanical = strain_increment;
      for (int i = 0; i < 3; ++i) mechanical[i] -= coupling.expansion * change;
      PointHistory none;
      PointHistory& h = history.empty() ? none : history[e];
      const double before = h.plastic_strain;
      now = law.at_temperature(temperature).update(rotated, mechanical, dt, h);
      // J2 flow: d eps_p = dp (3/2) s / q, so sigma : d eps_p = q dp with q the von Mises stress
      // after the return (the flow stress).
      if (!element_plastic_work.empty())
        element_plastic_work[e] = von_mises(now) * (h.plastic_strain - before) * mid_volume;
    }
  } else if constexpr (!std::is_same_v<Law, RubberLaw>) {  // hypoelastic laws (point_law.hpp)
    now = old;
    if (dt > 0.0) {
      PointHistory none;
      now = law.update(rotated, strain_increment, dt, history.empty() ? none : history[e]);
    }
  } else {
    // F = sum_a x_a (x) B0_a = sum_k c_k (x) R_k with R_k = 8 G0_k / V0 (hex8.hpp).
    const double* r0 = &reference_gradient[kReferenceModes * e];
    const double* cs[3] = {c.x, c.y, c.z};
    Mat3 f{};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        double sum = 0.0;
        for (int k = 1; k < 7; ++k) sum += cs[i][k] * r0[6 * j + k - 1];
        f[3 * i + j] = sum;
      }
    }
    now = mooney_rivlin_stress(*law.params, f);
    const Sym3 dev_increment = deviator(strain_increment);
    double* viscous_stress =
        viscous.data() + 6 * static_cast<std::size_t>(viscous_terms) * e;  // may be empty
    for (int k = 0; k < viscous_terms; ++k) {
      double* hk = viscous_stress + 6 * k;
      Sym3 h{{hk[0], hk[1], hk[2], hk[3], hk[4], hk[5]}};
      if (dt > 0.0) {
        const Sym3 hr = rotate(rotation, h);
        for (int comp = 0; comp < 6; ++comp) {
          h[comp] = law.viscous.decay[k] * hr[comp] + law.viscous.gain[k] * dev_increment[comp];
          hk[comp] = h[comp];
        }
      }
      now = add(now, h);
    }
  }
  for (int comp = 0; comp < 6; ++comp) stored[comp] = now[comp];
  internal_work[e] =
      dt > 0.0 ? 0.5 * double_dot(add(rotated, now), strain_increment) * mid_volume : 0.0;

  // 3. Artificial bulk viscosity in compression (von Neumann-Richtmyer quadratic plus a linear
  // term, LS-DYNA Theory Manual, "Artificial Bulk Viscosity"): an extra pressure
  //   q = rho l (C0 l eps_v_dot^2 - C1 c eps_v_dot),  eps_v_dot < 0,  l = V^(1/3),
  // that spreads shock fronts over a few elements and damps the ringing behind them. It is not
  // part of the stored stress; its work goes to the internal energy.
  double bulk_q = 0.0, q_speed = 0.0;
  if (dt > 0.0) {
    const double volume_rate =
        (strain_increment[0] + strain_increment[1] + strain_increment[2]) / dt;
    if (volume_rate < 0.0) {
      const double length = std::cbrt(g.volume);
      q_speed =
          bulk_viscosity_linear * wave_speed - bulk_viscosity_quadratic * length * volume_rate;
      bulk_q = -density * length * q_speed * volume_rate;
      internal_work[e] += -bulk_q * volume_rate * dt * mid_volume;
    }
  }

  // 4. Hourglass forces. With gamma_alpha(a) = h_alpha(a)/8 - (m_alpha . b_a)/V and the moment
  // m_alpha = c_{4+alpha}, the rate sum_a v_a gamma_alpha(a) is w_{4+alpha} - L^n m_alpha, where
  // L^n V = sum_a v_a (x) b_a is the velocity gradient at x^n times V; b:b = 8 sum_k G_k . G_k.
  double ln[9];
  gradient_times_volume(w, g, ln);
  const double inv_volume = 1.0 / g.volume;
  double bb = 0.0;
  for (int k = 0; k < 8; ++k) bb += g.gx[k] * g.gx[k] + g.gy[k] * g.gy[k] + g.gz[k] * g.gz[k];
  bb *= 8.0;
  const double stiffness = hourglass_coefficient * 2.0 * shear_modulus * bb / g.volume;
  const double* ws[3] = {w.x, w.y, w.z};
  double* q = &hourglass[12 * e];
  double work = 0.0;
  for (int alpha = 0; alpha < 4; ++alpha) {
    const int k = 4 + alpha;
    double rate[3];
    for (int i = 0; i < 3; ++i) {
      rate[i] = ws[i][k] -
                (ln[3 * i] * c.x[k] + ln[3 * i + 1] * c.y[k] + ln[3 * i + 2] * c.z[k]) * inv_volume;
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

  // 5. Nodal forces (acting on the nodes) f_a = -(sigma b_a + sum_alpha Q_alpha gamma_alpha(a)),
  // sigma including -q I. With b_a = sum_k phi_k(a) G_k and gamma as above this is
  // f_a = -sum_k phi_k(a) F_k, F_k = T G_k + Q_{k-4}/8 (k >= 4), T = sigma - (1/V) sum_alpha
  // Q_alpha (x) m_alpha: one 3x3 product per mode and the transform back to the nodes.
  double t[9] = {now[0] - bulk_q, now[3],          now[5],  //
                 now[3],          now[1] - bulk_q, now[4],  //
                 now[5],          now[4],          now[2] - bulk_q};
  for (int alpha = 0; alpha < 4; ++alpha) {
    const int k = 4 + alpha;
    for (int i = 0; i < 3; ++i) {
      const double qi = q[3 * alpha + i] * inv_volume;
      t[3 * i] -= qi * c.x[k];
      t[3 * i + 1] -= qi * c.y[k];
      t[3 * i + 2] -= qi * c.z[k];
    }
  }
  double modal_force[3][8];
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 8; ++k) {
      modal_force[i][k] = t[3 * i] * g.gx[k] + t[3 * i + 1] * g.gy[k] + t[3 * i + 2] * g.gz[k];
    }
    for (int alpha = 0; alpha < 4; ++alpha) modal_force[i][4 + alpha] += 0.125 * q[3 * alpha + i];
  }
  double nodal_force[3][8];
  for (int i = 0; i < 3; ++i) hex8_from_modes(modal_force[i], nodal_force[i]);
  double* fe = &forces[24 * e];
  double check = 0.0;
  for (int a = 0; a < 8; ++a) {
    for (int i = 0; i < 3; ++i) {
      fe[3 * a + i] = -nodal_force[i][a];
      check += std::abs(nodal_force[i][a]);
    }
  }
  if (!std::isfinite(check + internal_work[e] + work)) {
    failure[e] = kNonFinite;
    return;
  }

  // 6. Stable step.
  // With bulk viscosity the step shrinks to l / (Q + sqrt(Q^2 + c^2)), Q = C1 c + C0 l |eps_v_dot|
  // (same manual, "Time Step Control"). A Newtonian viscosity eta adds its longitudinal part the
  // same way: 4/3 eta eps_dot = rho l Q_eta eps_dot, Q_eta = 4 eta / (3 rho l).
  stable[e] = critical_step(hex8_critical_length(g, lame_lambda, lame_mu), q_speed);
  failure[e] = kOk;
  if (!eroded.empty()) {
    volume_ratio[e] = g.volume / reference_volume[e];
    if (erosion.max_geometric_strain < 1e20)
      geometric_strain[e] = deviatoric_log_strain(c, &reference_gradient[kReferenceModes * e]);
  }
}

template <class Law, bool kThermal>
BlockStep SolidBlock::Impl::step(const NodalState& s, double dt, const Law& law) {
  const auto n = static_cast<std::int64_t>(hexes.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMinimum / 8)
  for (std::int64_t e = 0; e < n; ++e)
    element<Law, kThermal>(static_cast<std::size_t>(e), s, dt, law);
  if constexpr (kThermal) temperature_started = true;

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
  if (!eroded.empty()) erode(out);
  out.internal_energy = internal_energy;
  out.hourglass_energy = hourglass_energy;
  out.eroded_energy = eroded_energy;
  out.eroded = eroded_count;
  return out;
}

// Serial, in element order: the energy each element has taken so far, then the criteria. An eroded
// element's energy leaves the internal (and hourglass) energy for the eroded energy, so the energy
// balance still closes; its forces of this step are dropped.
void SolidBlock::Impl::erode(BlockStep& out) {
  out.stable_step = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < hexes.size(); ++e) {
    if (eroded[e]) continue;
    element_internal[e] += internal_work[e];
    element_hourglass[e] += hourglass_work[e];
    const bool fails = stable[e] < erosion.min_step ||
                       geometric_strain[e] > erosion.max_geometric_strain ||
                       volume_ratio[e] - 1.0 > erosion.max_volumetric_strain ||
                       (fails_by_damage && history[e].failed());
    if (!fails) {
      out.stable_step = std::min(out.stable_step, stable[e]);
      continue;
    }
    eroded[e] = 1;
    ++eroded_count;
    eroded_energy += element_internal[e] + element_hourglass[e];
    internal_energy -= element_internal[e];
    hourglass_energy -= element_hourglass[e];
    std::fill_n(&forces[24 * e], 24, 0.0);
    std::fill_n(&stress[6 * e], 6, 0.0);
  }
}

SolidBlock::SolidBlock(std::int64_t part_id, const MaterialParams& material,
                       std::vector<Hex8> hexes, const Nodes& reference,
                       const FunctionTable* functions)
    : impl_(std::make_unique<Impl>()) {
  check_material(part_id, material, functions);
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
  m.stress.assign(6 * n, 0.0);
  m.viscous.assign(6 * static_cast<std::size_t>(m.viscous_terms) * n, 0.0);
  m.hourglass.assign(12 * n, 0.0);
  m.forces.assign(24 * n, 0.0);
  m.internal_work.assign(n, 0.0);
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

BlockStep SolidBlock::update(const NodalState& state, double dt) {
  if (!(dt >= 0.0) || !std::isfinite(dt)) {
    throw InstabilityError(input_prefix(impl_->part_id) + "time step must be finite and >= 0");
  }
  Impl& m = *impl_;
  if (m.coupled && state.temperature == nullptr)
    throw InputError(input_prefix(m.part_id) + "coupled to the temperature, but none was given");
  if (const auto* e = std::get_if<ElasticParams>(&m.material)) {
    const ElasticPoint law{lame_constants(*e)};
    return m.coupled ? m.step<ElasticPoint, true>(state, dt, law) : m.step(state, dt, law);
  }
  if (const auto* metal = std::get_if<MetalParams>(&m.material)) {
    const LameConstants lame{m.lame_lambda, m.lame_mu};
    const MetalPoint law{lame, FlowStress(*metal, m.functions), metal->failure};
    return m.coupled ? m.step<MetalPoint, true>(state, dt, law) : m.step(state, dt, law);
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

void SolidBlock::set_erosion(const ErosionCriteria& criteria) {
  Impl& m = *impl_;
  if (!(criteria.min_step >= 0.0) || !(criteria.max_geometric_strain > 0.0) ||
      !(criteria.max_volumetric_strain > 0.0))
    throw InputError(input_prefix(m.part_id) +
                     "erosion limits must be > 0 (the time step limit >= 0)");
  m.erosion = criteria;
  const std::size_t n = m.hexes.size();
  if (!criteria.any() && !m.fails_by_damage) {
    m.eroded.clear();
    return;
  }
  m.eroded.assign(n, 0);
  m.element_internal.assign(n, 0.0);
  m.element_hourglass.assign(n, 0.0);
  m.geometric_strain.assign(n, 0.0);
  m.volume_ratio.assign(n, 1.0);
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
  a.fixed(m.stress, m.viscous, m.hourglass, m.forces, m.internal_work, m.history, m.eroded,
          m.element_internal, m.element_hourglass, m.geometric_strain, m.volume_ratio,
          m.hourglass_work, m.stable, m.failure, m.element_temperature, m.element_plastic_work);
  a.values(m.eroded_energy, m.eroded_count, m.internal_energy, m.hourglass_energy,
           m.temperature_started);
}

void SolidBlock::set_element_ids(std::vector<std::int64_t> ids) {
  if (ids.size() != size()) {
    throw InputError(input_prefix(impl_->part_id) + "expected one element id per hexahedron");
  }
  impl_->element_ids = std::move(ids);
}

}  // namespace abut
