// The explicit update of a SolidBlock: the element kernel, the serial pass over its results and
// erosion. The mechanics are described at the top of solid_block.cpp.
//
// Evaluation: kLanes elements at once (lanes.hpp). Every step that is the same arithmetic for all
// elements (the modal transforms, gradients, rates, rotation, Hooke's law, the Mooney-Rivlin
// stress, hourglass forces, nodal forces, stable step) runs on Lanes, one element per lane; laws
// with history (metals), the bulk viscosity's cube root, the gather of the nodes and the writes of
// the results run element by element. Each lane sees exactly the operations of a lone element, so
// the results do not depend on the batching or on the number of threads.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#include "abut/core/error.hpp"
#include "abut/core/lanes.hpp"
#include "abut/core/parallel.hpp"
#include "abut/element/hex8.hpp"
#include "abut/element/stable_step.hpp"
#include "abut/material/elastic.hpp"
#include "abut/material/sym_tensor.hpp"
#include "block_step.hpp"
#include "solid_block_impl.hpp"

namespace abut {

// Effective deviatoric logarithmic strain sqrt(2/3 e_dev:e_dev) of F, from the eigenvalues of
// C = F^T F: e_i = ln(lambda_i) / 2.
double deviatoric_log_strain(const Mat3& f) {
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

namespace {

// sum_a u_a (x) b_a = 8 sum_k u_k (x) G_k (hex8.hpp), row-major: l[3 i + j] = sum_a u_ai b_aj.
template <class T>
[[gnu::always_inline]] inline void gradient_times_volume(const Hex8ModesOf<T>& u,
                                                         const Hex8ModalGradientOf<T>& g, T l[9]) {
  const T* us[3] = {u.x, u.y, u.z};
  for (int i = 0; i < 3; ++i) {
    T sx{}, sy{}, sz{};
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

// F = sum_a x_a (x) B0_a = sum_k c_k (x) R_k with R_k = 8 G0_k / V0 of the reference
// configuration (hex8.hpp), r0[6 j + k - 1] = component j of R_k; f row-major. T = double or
// Lanes.
template <class T>
void deformation_gradient(const Hex8ModesOf<T>& c, const T* r0, T f[9]) {
  const T* cs[3] = {c.x, c.y, c.z};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T sum{};
      for (int k = 1; k < 7; ++k) sum += cs[i][k] * r0[6 * j + k - 1];
      f[3 * i + j] = sum;
    }
}

double deviatoric_log_strain(const Hex8Modes& c, const double* r0) {
  Mat3 f;
  deformation_gradient(c, r0, f.data());
  return abut::deviatoric_log_strain(f);
}

// The lane l of a batch (Lanes, lanes.hpp) as one element's value.
Hex8Modes lane_of(const Hex8ModesOf<Lanes>& m, int l) {
  Hex8Modes out;
  for (int k = 0; k < 8; ++k) out.x[k] = m.x[k][l], out.y[k] = m.y[k][l], out.z[k] = m.z[k][l];
  return out;
}

template <std::size_t N>
std::array<double, N> lane_of(const Lanes (&v)[N], int l) {
  std::array<double, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = v[i][l];
  return out;
}

}  // namespace

void SolidBlock::Impl::clear_eroded(std::size_t e) {
  std::fill_n(&forces[24 * e], 24, 0.0);
  internal_work[e] = hourglass_work[e] = 0.0;
  if (!element_plastic_work.empty()) element_plastic_work[e] = 0.0;
  if (!element_thermal_work.empty()) element_thermal_work[e] = 0.0;
  stable[e] = std::numeric_limits<double>::infinity();
  failure[e] = kOk;
}

template <class Law, bool kThermal>
void SolidBlock::Impl::batch(std::size_t first, const NodalState& s, double dt, const Law& law) {
  // The lanes: elements first + l. Lanes past the block's end repeat its last element, and
  // eroded elements are evaluated as they are; neither changes its state (an eroded element's
  // forces, work and step are cleared here). A lane that fails (inverted) keeps its state and
  // writes only its failure, as a lone element would.
  const std::size_t n = hexes.size();
  std::size_t index[kLanes];
  bool live[kLanes];
  unsigned char fails[kLanes] = {};
  for (int l = 0; l < kLanes; ++l) {
    const std::size_t e = first + static_cast<std::size_t>(l);
    index[l] = std::min(e, n - 1);
    live[l] = e < n && (eroded.empty() || !eroded[e]);
    if (e < n && !live[l]) clear_eroded(e);
  }
  const auto check_volume = [&](const Lanes& volume) {
    for (int l = 0; l < kLanes; ++l)
      if (!fails[l] && !(volume[l] > 0.0))
        fails[l] = std::isfinite(volume[l]) ? kInverted : kNonFinite;
  };
  // An element to update: live and not failed.
  const auto updates = [&](int l) { return live[l] && !fails[l]; };

  // Gather the nodal data once and go to the modal form (hex8.hpp): every per-node sum below
  // (velocity gradients, F, hourglass rates, b:b) becomes a sum over the six modes with G_k != 0.
  Hex8ModesOf<Lanes> c, w;  // modes of x^n and of v^{n-1/2}
  {
    // Vector by vector (node a of every lane), so that each is built in registers.
    Lanes x[3][8], v[3][8];
    for (int a = 0; a < 8; ++a) {
      std::size_t node[kLanes];
      for (int l = 0; l < kLanes; ++l) node[l] = static_cast<std::size_t>(hexes[index[l]][a]);
      for (int l = 0; l < kLanes; ++l) {
        x[0][a][l] = s.x[node[l]];
        x[1][a][l] = s.y[node[l]];
        x[2][a][l] = s.z[node[l]];
        v[0][a][l] = s.vx[node[l]];
        v[1][a][l] = s.vy[node[l]];
        v[2][a][l] = s.vz[node[l]];
      }
    }
    hex8_to_modes(x[0], c.x);
    hex8_to_modes(x[1], c.y);
    hex8_to_modes(x[2], c.z);
    hex8_to_modes(v[0], w.x);
    hex8_to_modes(v[1], w.y);
    hex8_to_modes(v[2], w.z);
  }
  Hex8ModalGradientOf<Lanes> g;
  hex8_modal_gradient(c, g);
  check_volume(g.volume);

  // 1. Mid-step rates. The transform is linear, so the modes of x^{n-1/2} are c - dt/2 w.
  const Lanes zero{};
  Lanes strain_increment[6] = {zero, zero, zero, zero, zero, zero};
  Lanes rotation[9];
  for (int k = 0; k < 9; ++k) rotation[k] = zero + (k % 4 == 0 ? 1.0 : 0.0);
  Lanes mid_volume = g.volume;
  if (dt > 0.0) {
    Hex8ModesOf<Lanes> mid;
    for (int k = 0; k < 8; ++k) {
      mid.x[k] = c.x[k] - 0.5 * dt * w.x[k];
      mid.y[k] = c.y[k] - 0.5 * dt * w.y[k];
      mid.z[k] = c.z[k] - 0.5 * dt * w.z[k];
    }
    Hex8ModalGradientOf<Lanes> gm;
    hex8_modal_gradient(mid, gm);
    check_volume(gm.volume);
    mid_volume = gm.volume;
    Lanes l[9];  // velocity gradient times V_mid
    gradient_times_volume(w, gm, l);
    const Lanes scale = dt / gm.volume;
    strain_increment[0] = scale * l[0];
    strain_increment[1] = scale * l[4];
    strain_increment[2] = scale * l[8];
    strain_increment[3] = 0.5 * scale * (l[1] + l[3]);
    strain_increment[4] = 0.5 * scale * (l[5] + l[7]);
    strain_increment[5] = 0.5 * scale * (l[6] + l[2]);
    Lanes half_spin[9];  // W dt / 2
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        half_spin[3 * i + j] = 0.25 * scale * (l[3 * i + j] - l[3 * j + i]);
    }
    cayley_rotation_of(half_spin, rotation);
  }

  // 2. Stress: rotated on the lanes, the law element by element.
  Lanes old[6], rotated[6], now[6];
  double* const stored = &stress[batched(first, 0, 6)];  // the batch's stresses, whole
  std::memcpy(old, stored, sizeof(old));
  if (dt > 0.0)
    rotate_sym(rotation, old, rotated);
  else
    std::copy(old, old + 6, rotated);
  std::copy(rotated, rotated + 6, now);
  // A law without history that offers a lane form (ElasticPoint) updates all lanes at once.
  constexpr bool kLaneLaw = !kThermal && requires(const Law& m, const Lanes* in, Lanes* out) {
    m.update_lanes(in, in, out);
  };
  if constexpr (kLaneLaw) {
    if (dt > 0.0) law.update_lanes(rotated, strain_increment, now);
  }
  constexpr bool kRubber = std::is_same_v<Law, RubberLaw>;
  if constexpr (kRubber) {
    // F = sum_k c_k (x) R_k (deformation_gradient), its elastic stress, and the viscous stresses
    // rotated and recursively updated (mooney_rivlin.hpp), on the lanes.
    Lanes r0[kReferenceModes];
    for (std::size_t m = 0; m < kReferenceModes; ++m)
      for (int l = 0; l < kLanes; ++l)
        r0[m][l] = reference_gradient[kReferenceModes * index[l] + m];
    Lanes f[9];
    deformation_gradient(c, r0, f);
    mooney_rivlin_stress_of(*law.params, f, now);
    Lanes dev_increment[6];
    deviator_of(strain_increment, dev_increment);
    const auto terms = static_cast<std::size_t>(viscous_terms);
    for (int k = 0; k < viscous_terms; ++k) {
      const auto at = [&](int l, int comp) {  // term k of the element in lane l
        return (terms * index[l] + static_cast<std::size_t>(k)) * 6 +
               static_cast<std::size_t>(comp);
      };
      // Filled through a plain array: g++ 12 at -march=native took a lane-wise fill of h for a
      // partial one (-Wmaybe-uninitialized).
      Lanes h[6];
      for (int comp = 0; comp < 6; ++comp) {
        double term[kLanes];
        for (int l = 0; l < kLanes; ++l) term[l] = viscous[at(l, comp)];
        std::memcpy(&h[comp], term, sizeof(Lanes));
      }
      if (dt > 0.0) {
        Lanes hr[6];
        rotate_sym(rotation, h, hr);
        for (int comp = 0; comp < 6; ++comp)
          h[comp] = law.viscous.decay[k] * hr[comp] + law.viscous.gain[k] * dev_increment[comp];
        for (int l = 0; l < kLanes; ++l)
          if (updates(l))
            for (int comp = 0; comp < 6; ++comp) viscous[at(l, comp)] = h[comp][l];
      }
      for (int comp = 0; comp < 6; ++comp) now[comp] = now[comp] + h[comp];
    }
  }
  // The work of the stresses on the thermal strain increment alpha dT I, per lane (thermal laws).
  Lanes thermal = zero;
  // Other laws (with history), element by element.
  if constexpr (!kLaneLaw && !kRubber) {
    for (int l = 0; l < kLanes; ++l) {
      if (!updates(l)) continue;
      const std::size_t e = index[l];
      const Sym3 rotated_l{lane_of(rotated, l)}, increment{lane_of(strain_increment, l)};
      Sym3 now_l;
      if constexpr (kThermal) {  // hypoelastic point laws coupled to the temperature
        // The element temperature, and the thermal strain increment alpha dT I of its change
        // since the last update taken out of the total increment (the mechanical strain drives
        // the law).
        double temperature = 0.0;
        for (int a = 0; a < 8; ++a)
          temperature += s.temperature[static_cast<std::size_t>(hexes[e][a])];
        temperature *= 0.125;
        double& last = element_temperature[e];
        const double change = temperature_started ? temperature - last : 0.0;
        last = temperature;
        now_l = Sym3{lane_of(old, l)};
        if (!element_plastic_work.empty()) element_plastic_work[e] = 0.0;
        if (dt > 0.0) {
          Sym3 mechanical = increment;
          for (int i = 0; i < 3; ++i) mechanical[i] -= coupling.expansion * change;
          PointHistory none;
          PointHistory& h = history.empty() ? none : history[e];
          const double before = h.plastic_strain;
          now_l = law.at_temperature(temperature).update(rotated_l, mechanical, dt, h);
          // J2 flow: d eps_p = dp (3/2) s / q, so sigma : d eps_p = q dp with q the von Mises
          // stress after the return (the flow stress).
          if (!element_plastic_work.empty())
            element_plastic_work[e] =
                von_mises(now_l) * (h.plastic_strain - before) * mid_volume[l];
          // Trapezoidal, as the internal work below: 0.5 tr(sigma_rot + sigma_new) alpha dT V.
          thermal[l] =
              0.5 * (rotated_l[0] + rotated_l[1] + rotated_l[2] + now_l[0] + now_l[1] + now_l[2]) *
              coupling.expansion * change * mid_volume[l];
        }
      } else {  // hypoelastic laws (point_law.hpp)
        now_l = Sym3{lane_of(old, l)};
        if (dt > 0.0) {
          PointHistory none;
          now_l = law.update(rotated_l, increment, dt, history.empty() ? none : history[e]);
        }
      }
      for (int comp = 0; comp < 6; ++comp) now[comp][l] = now_l[comp];
    }
  }
  // Trapezoidal work 0.5 (sigma_rot + sigma_new) : D dt V_mid.
  Lanes internal = zero;
  if (dt > 0.0) {
    Lanes sum[6];
    for (int comp = 0; comp < 6; ++comp) sum[comp] = rotated[comp] + now[comp];
    internal = 0.5 * double_dot_of(sum, strain_increment) * mid_volume;
    // The stresses' work on the total strain, less that on the thermal strain: the internal
    // energy is the work on the mechanical strain (stored and dissipated). Minus the work on the
    // thermal strain is the energy the expansion brings into the mechanics (a bar held at both
    // ends and heated: compressive stress, growing thermal strain, energy in;
    // Energies::thermal_work): kinetic + internal = external + thermal work.
    if constexpr (kThermal) internal -= thermal;
  }

  // 3. Artificial bulk viscosity in compression (von Neumann-Richtmyer quadratic plus a linear
  // term, LS-DYNA Theory Manual, "Artificial Bulk Viscosity"): an extra pressure
  //   q = rho l (C0 l eps_v_dot^2 - C1 c eps_v_dot),  eps_v_dot < 0,  l = V^(1/3),
  // that spreads shock fronts over a few elements and damps the ringing behind them. It is not
  // part of the stored stress; its work goes to the internal energy. Over the step just taken,
  // the work of its nodal forces as the kinetic energy's product form sees it (forces at the
  // step's two ends, each over half of it), the mean of last update's q and this one's times the
  // volume change, like the stresses' work above: q alone over-books it by q times the change of
  // the volume rate, up to 2% of the energy of a ringing block (issue 27).
  Lanes bulk_q = zero, q_speed = zero;
  if (dt > 0.0) {
    Lanes q_before = zero;
    for (int l = 0; l < kLanes; ++l) q_before[l] = bulk_pressure[index[l]];
    const Lanes volume_rate =
        (strain_increment[0] + strain_increment[1] + strain_increment[2]) / dt;
    const auto compressed = volume_rate < 0.0;
    Lanes length = zero;  // the cube root only where it is needed
    for (int l = 0; l < kLanes; ++l)
      if (compressed[l]) length[l] = std::cbrt(g.volume[l]);
    const Lanes speed =
        bulk_viscosity_linear * wave_speed - bulk_viscosity_quadratic * length * volume_rate;
    const Lanes pressure = -density * length * speed * volume_rate;
    q_speed = compressed ? speed : zero;
    bulk_q = compressed ? pressure : zero;
    internal += -0.5 * (q_before + bulk_q) * volume_rate * dt * mid_volume;
  }

  // 4. Hourglass forces. With gamma_alpha(a) = h_alpha(a)/8 - (m_alpha . b_a)/V and the moment
  // m_alpha = c_{4+alpha}, the rate sum_a v_a gamma_alpha(a) is w_{4+alpha} - L^n m_alpha, where
  // L^n V = sum_a v_a (x) b_a is the velocity gradient at x^n times V; b:b = 8 sum_k G_k . G_k.
  Lanes ln[9];
  gradient_times_volume(w, g, ln);
  const Lanes inv_volume = 1.0 / g.volume;
  Lanes bb = zero;
  for (int k = 0; k < 8; ++k) bb += g.gx[k] * g.gx[k] + g.gy[k] * g.gy[k] + g.gz[k] * g.gz[k];
  bb *= 8.0;
  const Lanes stiffness = hourglass_coefficient * 2.0 * shear_modulus * bb / g.volume;
  const Lanes* ws[3] = {w.x, w.y, w.z};
  Lanes q[12];
  double* const stored_q = &hourglass[batched(first, 0, 12)];
  std::memcpy(q, stored_q, sizeof(q));
  Lanes q_old[12];
  std::copy(q, q + 12, q_old);
  Lanes work = zero;
  for (int alpha = 0; alpha < 4; ++alpha) {
    const int k = 4 + alpha;
    Lanes rate[3];
    for (int i = 0; i < 3; ++i) {
      rate[i] = ws[i][k] -
                (ln[3 * i] * c.x[k] + ln[3 * i + 1] * c.y[k] + ln[3 * i + 2] * c.z[k]) * inv_volume;
    }
    Lanes* qa = q + 3 * alpha;
    Lanes qr[3] = {qa[0], qa[1], qa[2]};
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

  // 5. Nodal forces (acting on the nodes) f_a = -(sigma b_a + sum_alpha Q_alpha gamma_alpha(a)),
  // sigma including -q I. With b_a = sum_k phi_k(a) G_k and gamma as above this is
  // f_a = -sum_k phi_k(a) F_k, F_k = T G_k + Q_{k-4}/8 (k >= 4), T = sigma - (1/V) sum_alpha
  // Q_alpha (x) m_alpha: one 3x3 product per mode and the transform back to the nodes.
  Lanes t[9] = {now[0] - bulk_q, now[3],          now[5],  //
                now[3],          now[1] - bulk_q, now[4],  //
                now[5],          now[4],          now[2] - bulk_q};
  for (int alpha = 0; alpha < 4; ++alpha) {
    const int k = 4 + alpha;
    for (int i = 0; i < 3; ++i) {
      const Lanes qi = q[3 * alpha + i] * inv_volume;
      t[3 * i] -= qi * c.x[k];
      t[3 * i + 1] -= qi * c.y[k];
      t[3 * i + 2] -= qi * c.z[k];
    }
  }
  Lanes nodal_force[3][8];
  Lanes finite = internal - internal + (work - work);  // x - x: 0 if x is finite, else NaN
  for (int i = 0; i < 3; ++i) {
    Lanes modal_force[8];
    for (int k = 0; k < 8; ++k) {
      modal_force[k] = t[3 * i] * g.gx[k] + t[3 * i + 1] * g.gy[k] + t[3 * i + 2] * g.gz[k];
    }
    for (int alpha = 0; alpha < 4; ++alpha) modal_force[4 + alpha] += 0.125 * q[3 * alpha + i];
    hex8_from_modes(modal_force, nodal_force[i]);
    for (int a = 0; a < 8; ++a) finite += nodal_force[i][a] - nodal_force[i][a];
  }

  // 6. Stable step.
  // With bulk viscosity the step shrinks to l / (Q + sqrt(Q^2 + c^2)), Q = C1 c + C0 l |eps_v_dot|
  // (same manual, "Time Step Control"). A Newtonian viscosity eta adds its longitudinal part the
  // same way: 4/3 eta eps_dot = rho l Q_eta eps_dot, Q_eta = 4 eta / (3 rho l).
  Lanes product[6];
  hex8_gradient_products(g, product);
  const Lanes step =
      critical_step(hex8_critical_length(product, g.volume, lame_lambda, lame_mu), q_speed);

  // The results. The batch's state whole: the elements updated take the new, the others keep
  // theirs (failed, eroded, or lanes past the end).
  using LaneMask = decltype(zero < zero);
  LaneMask write{};
  for (int l = 0; l < kLanes; ++l) write[l] = updates(l) ? -1 : 0;
  for (int comp = 0; comp < 6; ++comp) now[comp] = write ? now[comp] : old[comp];
  for (int i = 0; i < 12; ++i) q[i] = write ? q[i] : q_old[i];
  std::memcpy(stored, now, sizeof(now));
  std::memcpy(stored_q, q, sizeof(q));
  for (int l = 0; l < kLanes; ++l) {
    if (!live[l]) continue;
    const std::size_t e = index[l];
    failure[e] = fails[l];
    if (fails[l]) continue;
    internal_work[e] = internal[l];
    bulk_pressure[e] = bulk_q[l];
    if constexpr (kThermal) element_thermal_work[e] = thermal[l];
    hourglass_work[e] = work[l];
    double* fe = &forces[24 * e];
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i) fe[3 * a + i] = -nodal_force[i][a][l];
    if (!(finite[l] == 0.0)) {
      failure[e] = kNonFinite;
      continue;
    }
    stable[e] = step[l];
    if (!eroded.empty()) {
      volume_ratio[e] = g.volume[l] / reference_volume[e];
      if (erosion.max_geometric_strain < 1e20)
        geometric_strain[e] =
            deviatoric_log_strain(lane_of(c, l), &reference_gradient[kReferenceModes * e]);
    }
  }
}

template <class Law, bool kThermal>
BlockStep SolidBlock::Impl::step(const NodalState& s, double dt, const Law& law) {
  const auto n = static_cast<std::int64_t>(hexes.size());
  const std::int64_t batches = (n + kLanes - 1) / kLanes;
#pragma omp parallel for schedule(static) if (n >= kParallelMinimum / 8)
  for (std::int64_t b = 0; b < batches; ++b)
    batch<Law, kThermal>(static_cast<std::size_t>(b * kLanes), s, dt, law);
  if constexpr (kThermal) temperature_started = true;

  static_assert(kInverted == 1 && kNonFinite == 2, "the messages below, by failure code");
  BlockStep out = end_block_step(
      *this, hexes.size(),
      {nullptr, ": inverted element (volume <= 0)", ": non-finite volume, stress or force"});
  if constexpr (kThermal) {
    for (std::size_t e = 0; e < hexes.size(); ++e)
      if (eroded.empty() || !eroded[e]) thermal_work -= element_thermal_work[e];
    out.thermal_work = thermal_work;
  }
  return out;
}

void SolidBlock::Impl::erode(BlockStep& out) {
  erode_elements(
      *this, hexes.size(), 24, out,
      [this](std::size_t e) {
        return stable[e] < erosion.min_step || geometric_strain[e] > erosion.max_geometric_strain ||
               volume_ratio[e] - 1.0 > erosion.max_volumetric_strain ||
               (fails_by_damage && history[e].failed());
      },
      [this](std::size_t e) {
        for (int c = 0; c < 6; ++c) stress[batched(e, c, 6)] = 0.0;
      });
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

}  // namespace abut
