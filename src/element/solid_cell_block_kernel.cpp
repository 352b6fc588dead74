// The explicit update of a SolidCellBlock (solid_cell_block.hpp), element by element; each
// element writes only its own state, so the results do not depend on the number of threads.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "abut/core/error.hpp"
#include "abut/core/parallel.hpp"
#include "abut/material/elastic.hpp"
#include "abut/material/mooney_rivlin.hpp"
#include "block_step.hpp"
#include "solid_cell_block_impl.hpp"

namespace abut {

namespace {

// The most active viscous terms of a Mooney-Rivlin law.
constexpr int kMaxViscousTerms = 4;

// J_ir = dx_i / dxi_r at a point from the natural derivatives dn of `nodes` shape functions.
Mat3 natural_jacobian(int nodes, const double (*dn)[3], const double* x) {
  Mat3 j{};
  for (int a = 0; a < nodes; ++a)
    for (int i = 0; i < 3; ++i)
      for (int r = 0; r < 3; ++r) j[3 * i + r] += x[3 * a + i] * dn[a][r];
  return j;
}

// F = dx/dX = J(x) J(X)^-1 at a point (row-major), J(X) by cofactors.
Mat3 deformation_gradient(int nodes, const double (*dn)[3], const double* x, const double* X) {
  const Mat3 j = natural_jacobian(nodes, dn, x), m = natural_jacobian(nodes, dn, X);
  const double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                     m[2] * (m[3] * m[7] - m[4] * m[6]);
  const Mat3 inverse = {(m[4] * m[8] - m[5] * m[7]) / det, (m[2] * m[7] - m[1] * m[8]) / det,
                        (m[1] * m[5] - m[2] * m[4]) / det, (m[5] * m[6] - m[3] * m[8]) / det,
                        (m[0] * m[8] - m[2] * m[6]) / det, (m[2] * m[3] - m[0] * m[5]) / det,
                        (m[3] * m[7] - m[4] * m[6]) / det, (m[1] * m[6] - m[0] * m[7]) / det,
                        (m[0] * m[4] - m[1] * m[3]) / det};
  Mat3 f{};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int r = 0; r < 3; ++r) f[3 * i + k] += j[3 * i + r] * inverse[3 * r + k];
  return f;
}

}  // namespace

template <class Law>
void SolidCellBlock::Impl::element(std::size_t e, const NodalState& s, double dt, const Law& law) {
  const auto nn = static_cast<std::size_t>(nodes), np = static_cast<std::size_t>(points);
  double* const force = &forces[3 * nn * e];
  if (!eroded.empty() && eroded[e]) {
    std::fill_n(force, 3 * nn, 0.0);
    internal_work[e] = hourglass_work[e] = 0.0;
    stable[e] = std::numeric_limits<double>::infinity();
    failure[e] = kOk;
    return;
  }
  double x[3 * kMaxCellNodes], v[3 * kMaxCellNodes], mid[3 * kMaxCellNodes];
  gather(e, s.x, s.y, s.z, x);
  gather(e, s.vx, s.vy, s.vz, v);
  for (std::size_t k = 0; k < 3 * nn; ++k) mid[k] = x[k] - 0.5 * dt * v[k];
  const auto fail = [&](double det) { failure[e] = std::isfinite(det) ? kInverted : kNonFinite; };

  // 1. Gradients and volume at x^n.
  double grad[kMaxPoints][kMaxCellNodes][3], dv[kMaxPoints];
  double volume = 0.0;
  for (std::size_t q = 0; q < np; ++q) {
    const double det = natural_to_spatial(nodes, natural_at(q), x, grad[q]);
    if (!(det > 0.0)) return fail(det);
    dv[q] = weight[q] * det;
    volume += dv[q];
  }

  // 2. The stress at each point: rates at x^{n-1/2}, rotation, law. Kept aside until the
  // element is known to be sound.
  Sym3 now[kMaxPoints];
  PointHistory histories[kMaxPoints];
  double new_viscous[kMaxPoints][kMaxViscousTerms][6];
  double internal = 0.0, mid_volume = 0.0, volume_change = 0.0, geometric = 0.0;
  constexpr bool kRubber = std::is_same_v<Law, RubberLaw>;
  for (std::size_t q = 0; q < np; ++q) {
    const std::size_t p = e * np + q;
    Sym3 old;
    std::copy_n(&stress[6 * p], 6, old.c.begin());
    Sym3 rotated = old, increment, averaged;
    double rotation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double dv_mid = 0.0;
    if (dt > 0.0) {
      double g[kMaxCellNodes][3];
      const double det = natural_to_spatial(nodes, natural_at(q), mid, g);
      if (!(det > 0.0)) return fail(det);
      dv_mid = weight[q] * det;
      double l[3][3] = {};
      for (std::size_t a = 0; a < nn; ++a)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) l[i][j] += v[3 * a + i] * g[a][j];
      increment = Sym3{{l[0][0] * dt, l[1][1] * dt, l[2][2] * dt, 0.5 * (l[0][1] + l[1][0]) * dt,
                        0.5 * (l[1][2] + l[2][1]) * dt, 0.5 * (l[2][0] + l[0][2]) * dt}};
      double half_spin[9];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) half_spin[3 * i + j] = 0.25 * dt * (l[i][j] - l[j][i]);
      cayley_rotation_of(half_spin, rotation);
      rotate_sym(rotation, old.c.data(), rotated.c.data());
    }
    if constexpr (kRubber) {
      // F = dx/dX = J(x^n) J(X)^-1 at the point, its elastic stress, and the viscous stresses
      // rotated and recursively updated (mooney_rivlin.hpp), as SolidBlock.
      const Mat3 f = deformation_gradient(nodes, natural_at(q), x, &reference[3 * nn * e]);
      now[q] = mooney_rivlin_stress(*law.params, f);
      if (nodal_pressure) {  // the pressure K (J - 1) of the mean of the nodes' volume ratios
        double j_mean = 0.0;
        for (std::size_t a = 0; a < nn; ++a) {
          const auto l = static_cast<std::size_t>(local_node[e * nn + a]);
          j_mean += node_weight[l] / node_value[l];
        }
        j_mean /= static_cast<double>(nn);
        const double j = f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
                         f[2] * (f[3] * f[7] - f[4] * f[6]);
        for (int c = 0; c < 3; ++c) now[q][c] += law.params->bulk * (j_mean - j);
      }
      const Sym3 dev = deviator(increment);
      for (int k = 0; k < viscous_terms; ++k) {
        double* h = new_viscous[q][k];
        std::copy_n(&viscous[(p * static_cast<std::size_t>(viscous_terms) + k) * 6], 6, h);
        if (dt > 0.0) {
          double hr[6];
          rotate_sym(rotation, h, hr);
          for (int c = 0; c < 6; ++c)
            h[c] = law.viscous.decay[k] * hr[c] + law.viscous.gain[k] * dev[c];
        }
        for (int c = 0; c < 6; ++c) now[q][c] += h[c];
      }
      if (erosion.max_geometric_strain < 1e20 && !eroded.empty())
        geometric += point_share[p] * deviatoric_log_strain(f);
    } else {
      if (nodal_pressure && dt > 0.0) {  // the volumetric increment: the mean of the nodes'
        double mean = 0.0;
        for (std::size_t a = 0; a < nn; ++a) {
          const auto l = static_cast<std::size_t>(local_node[e * nn + a]);
          mean += node_value[l] / node_weight[l];
        }
        mean /= static_cast<double>(nn);
        const double shift = (mean - trace(increment)) / 3.0;
        for (int c = 0; c < 3; ++c) averaged[c] = increment[c] + shift;
        for (int c = 3; c < 6; ++c) averaged[c] = increment[c];
      }
      now[q] = old;
      if (!history.empty()) histories[q] = history[p];
      if (dt > 0.0)
        now[q] = law.update(rotated, nodal_pressure ? averaged : increment, dt, histories[q]);
      if (erosion.max_geometric_strain < 1e20 && !eroded.empty()) {
        const Mat3 f = deformation_gradient(nodes, natural_at(q), x, &reference[3 * nn * e]);
        geometric += point_share[p] * deviatoric_log_strain(f);
      }
    }
    // Trapezoidal work 0.5 (sigma_rot + sigma_new) : D dt dV_mid, as SolidBlock.
    internal += 0.5 * double_dot(add(rotated, now[q]), increment) * dv_mid;
    mid_volume += dv_mid;
    volume_change += trace(increment) * dv_mid;
  }

  // 3. Bulk viscosity on the element's mean volume rate (SolidBlock, step 3).
  double bulk_q = 0.0, q_speed = 0.0;
  if (dt > 0.0) {
    const double volume_rate = volume_change / (mid_volume * dt);
    if (volume_rate < 0.0) {
      const double length = std::cbrt(volume);
      q_speed =
          bulk_viscosity_linear * wave_speed - bulk_viscosity_quadratic * length * volume_rate;
      bulk_q = -density * length * q_speed * volume_rate;
    }
    internal += -0.5 * (bulk_pressure[e] + bulk_q) * volume_rate * dt * mid_volume;
  }

  // 4. Nodal forces acting on the nodes at x^n: f_a = -sum_q (sigma_q - q I) grad N_a dV_q.
  std::fill_n(force, 3 * nn, 0.0);
  for (std::size_t q = 0; q < np; ++q) {
    const Sym3& t = now[q];
    const double sxx = t[0] - bulk_q, syy = t[1] - bulk_q, szz = t[2] - bulk_q;
    for (std::size_t a = 0; a < nn; ++a) {
      const double* b = grad[q][a];
      force[3 * a] -= (sxx * b[0] + t[3] * b[1] + t[5] * b[2]) * dv[q];
      force[3 * a + 1] -= (t[3] * b[0] + syy * b[1] + t[4] * b[2]) * dv[q];
      force[3 * a + 2] -= (t[5] * b[0] + t[4] * b[1] + szz * b[2]) * dv[q];
    }
  }
  double finite = internal - internal;
  for (std::size_t k = 0; k < 3 * nn; ++k) finite += force[k] - force[k];
  if (!(finite == 0.0)) {
    failure[e] = kNonFinite;
    return;
  }

  // 5. Commit the element's state.
  for (std::size_t q = 0; q < np; ++q) {
    const std::size_t p = e * np + q;
    std::copy(now[q].c.begin(), now[q].c.end(), &stress[6 * p]);
    if (!history.empty()) history[p] = histories[q];
    for (int k = 0; k < viscous_terms; ++k)
      std::copy_n(new_viscous[q][k], 6,
                  &viscous[(p * static_cast<std::size_t>(viscous_terms) + k) * 6]);
  }
  failure[e] = kOk;
  internal_work[e] = internal;
  hourglass_work[e] = 0.0;
  bulk_pressure[e] = bulk_q;
  stable[e] = critical_step(length_factor[e] * characteristic_length(x, volume), q_speed);
  if (!eroded.empty()) {
    volume_ratio[e] = volume / reference_volume[e];
    geometric_strain[e] = geometric;
  }
}

// The nodal sums of the average nodal pressure (set_nodal_pressure; one point per element).
template <class Law>
void SolidCellBlock::Impl::average_nodal_volumes(const NodalState& s, double dt) {
  constexpr bool kRubber = std::is_same_v<Law, RubberLaw>;
  const auto n = static_cast<std::int64_t>(size());
  const auto nn = static_cast<std::size_t>(nodes);
#pragma omp parallel for schedule(static) if (n >= kParallelMinimum)
  for (std::int64_t k = 0; k < n; ++k) {
    const auto e = static_cast<std::size_t>(k);
    element_weight[e] = element_value[e] = 0.0;
    if (!eroded.empty() && eroded[e]) continue;
    double x[3 * kMaxCellNodes], v[3 * kMaxCellNodes], g[kMaxCellNodes][3];
    gather(e, s.x, s.y, s.z, x);
    if constexpr (kRubber) {  // V(x^n) and V(X)
      element_weight[e] = weight[0] * natural_to_spatial(nodes, natural_at(0), x, g);
      element_value[e] = reference_volume[e];
    } else {  // V(x^{n-1/2}) and V tr(D dt)
      gather(e, s.vx, s.vy, s.vz, v);
      for (std::size_t i = 0; i < 3 * nn; ++i) x[i] -= 0.5 * dt * v[i];
      const double volume = weight[0] * natural_to_spatial(nodes, natural_at(0), x, g);
      double rate = 0.0;
      for (std::size_t a = 0; a < nn; ++a)
        rate += v[3 * a] * g[a][0] + v[3 * a + 1] * g[a][1] + v[3 * a + 2] * g[a][2];
      element_weight[e] = volume;
      element_value[e] = volume * rate * dt;
    }
  }
  // Serial, in element order: the sums do not depend on the number of threads. An inverted
  // element leaves a non-positive weight, which the element's own update reports.
  std::fill(node_weight.begin(), node_weight.end(), 0.0);
  std::fill(node_value.begin(), node_value.end(), 0.0);
  for (std::size_t e = 0; e < size(); ++e)
    for (std::size_t a = 0; a < nn; ++a) {
      const auto l = static_cast<std::size_t>(local_node[e * nn + a]);
      node_weight[l] += 0.25 * element_weight[e];
      node_value[l] += 0.25 * element_value[e];
    }
}

template <class Law>
BlockStep SolidCellBlock::Impl::step(const NodalState& s, double dt, const Law& law) {
  const auto n = static_cast<std::int64_t>(size());
  if (nodal_pressure && (dt > 0.0 || std::is_same_v<Law, RubberLaw>))
    average_nodal_volumes<Law>(s, dt);
#pragma omp parallel for schedule(static) if (n * points >= kParallelMinimum)
  for (std::int64_t e = 0; e < n; ++e) element(static_cast<std::size_t>(e), s, dt, law);
  static_assert(kInverted == 1 && kNonFinite == 2, "the messages below, by failure code");
  return end_block_step(*this, size(),
                        {nullptr, ": inverted element (Jacobian <= 0 at an integration point)",
                         ": non-finite volume, stress or force"});
}

void SolidCellBlock::Impl::erode(BlockStep& out) {
  const auto np = static_cast<std::size_t>(points);
  erode_elements(
      *this, size(), 3 * static_cast<std::size_t>(nodes), out,
      [&](std::size_t e) {
        bool all_failed = fails_by_damage;
        for (std::size_t q = 0; all_failed && q < np; ++q)
          all_failed = history[e * np + q].failed();
        return stable[e] < erosion.min_step || geometric_strain[e] > erosion.max_geometric_strain ||
               volume_ratio[e] - 1.0 > erosion.max_volumetric_strain || all_failed;
      },
      [&](std::size_t e) {
        std::fill_n(&stress[6 * np * e], 6 * np, 0.0);
        const std::size_t terms = 6 * static_cast<std::size_t>(viscous_terms) * np;
        std::fill_n(viscous.begin() + static_cast<std::ptrdiff_t>(terms * e), terms, 0.0);
      });
}

BlockStep SolidCellBlock::update(const NodalState& state, double dt) {
  if (!(dt >= 0.0) || !std::isfinite(dt))
    throw InstabilityError(input_prefix(impl_->part_id) + "time step must be finite and >= 0");
  Impl& m = *impl_;
  if (const auto* elastic = std::get_if<ElasticParams>(&m.material))
    return m.step(state, dt, ElasticPoint{lame_constants(*elastic)});
  if (const auto* metal = std::get_if<MetalParams>(&m.material))
    return m.step(state, dt,
                  MetalPoint{LameConstants{m.lame_lambda, m.lame_mu},
                             FlowStress(*metal, m.functions), metal->failure});
  const auto& rubber = std::get<MooneyRivlinParams>(m.material);
  return m.step(state, dt, RubberLaw{&rubber, dt > 0.0 ? viscous_step(rubber, dt) : ViscousStep{}});
}

}  // namespace abut
