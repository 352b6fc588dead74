#include "abut/element/shell_block.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "abut/core/error.hpp"
#include "abut/core/parallel.hpp"
#include "abut/core/state_archive.hpp"
#include "abut/element/shell4.hpp"
#include "abut/material/point_law.hpp"
#include "block_step.hpp"

namespace abut {

void gauss_legendre(int n, std::vector<double>& points, std::vector<double>& weights) {
  points.assign(static_cast<std::size_t>(n), 0.0);
  weights.assign(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    // Newton on P_n from the Chebyshev-like first guess (Abramowitz & Stegun 22.16.6).
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;  // P_0, P_1; recurrence (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}
      for (int k = 1; k < n; ++k) {
        const double p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    points[static_cast<std::size_t>(n - 1 - i)] = x;  // ascending
    weights[static_cast<std::size_t>(n - 1 - i)] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
  if (n % 2 == 1) points[static_cast<std::size_t>(n / 2)] = 0.0;  // exactly the mid-surface
}

namespace {

enum Failure : unsigned char { kOk = 0, kDegenerate = 1, kNonFinite = 2 };

std::string part_prefix(std::int64_t part_id) {
  std::string s("part ");
  s += std::to_string(part_id);
  s += ": ";
  return s;
}

}  // namespace

struct ShellBlock::Impl {
  std::int64_t part_id = 0;
  MaterialParams material;
  ShellSection section;
  std::vector<Quad4> shells;
  std::vector<std::int64_t> element_ids;
  const FunctionTable* functions = nullptr;
  double density = 0.0, young = 0.0, poisson = 0.0;
  LameConstants lame;
  double wave_speed = 0.0;           // plate wave speed sqrt(E / (rho (1 - nu^2)))
  std::vector<double> zeta, weight;  // Gauss points and weights through the thickness

  std::vector<double> reference_area;
  std::vector<double> reference_b;  // erosion strain: b1, b2 of the reference frame, 8 per element
  std::vector<double> stress;       // 6 per point
  std::vector<PointHistory> history;    // 1 per point (metals)
  std::vector<double> thickness_ratio;  // 1 per point (metals): last d_zz / (d_xx + d_yy)
  bool fails_by_damage = false;         // erodes when every thickness point has failed
  std::vector<double> hourglass;        // 5 generalized hourglass forces per element
  std::vector<double> forces;           // 24 per element
  std::vector<double> internal_work, hourglass_work, stable;
  std::vector<unsigned char> failure;
  double internal_energy = 0.0, hourglass_energy = 0.0;

  ErosionCriteria erosion;
  std::vector<std::uint8_t> eroded;
  std::vector<double> element_internal, element_hourglass, geometric_strain, area_ratio;
  double eroded_energy = 0.0;
  std::size_t eroded_count = 0;

  std::size_t points() const { return zeta.size(); }
  std::string element_name(std::size_t e) const {
    std::string name("part ");
    name += std::to_string(part_id);
    name += ", shell ";
    name += e < element_ids.size() ? std::to_string(element_ids[e])
                                   : "index " + std::to_string(e) + " in block";
    return name;
  }
  template <class Law>
  void element(std::size_t e, const ShellNodalState& s, double dt, const Law& law);
  template <class Law>
  BlockStep step(const ShellNodalState& s, double dt, const Law& law);
  void erode(BlockStep& out);
};

// Effective deviatoric logarithmic strain sqrt(2/3 e:e) of the mid-surface from the in-plane
// stretches, with the thickness strain -(e1 + e2) of an isochoric (plastic) deformation.
static double membrane_log_strain(const Shell4Geometry& g, const double* b0) {
  double f[4] = {0, 0, 0, 0};  // F = sum_a (x_a, y_a) (x) (b1_a, b2_a) of the reference
  for (int a = 0; a < 4; ++a) {
    f[0] += g.x[a] * b0[a];
    f[1] += g.x[a] * b0[4 + a];
    f[2] += g.y[a] * b0[a];
    f[3] += g.y[a] * b0[4 + a];
  }
  const double c11 = f[0] * f[0] + f[2] * f[2], c22 = f[1] * f[1] + f[3] * f[3];
  const double c12 = f[0] * f[1] + f[2] * f[3];
  const double mean = 0.5 * (c11 + c22);
  const double radius = std::sqrt(0.25 * (c11 - c22) * (c11 - c22) + c12 * c12);
  const double e1 = 0.5 * std::log(mean + radius),
               e2 = 0.5 * std::log(std::max(mean - radius, 1e-300));
  const double e3 = -(e1 + e2);
  return std::sqrt(2.0 / 3.0 * (e1 * e1 + e2 * e2 + e3 * e3));
}

template <class Law>
void ShellBlock::Impl::element(std::size_t e, const ShellNodalState& s, double dt, const Law& law) {
  double* f = &forces[24 * e];
  internal_work[e] = 0.0;
  hourglass_work[e] = 0.0;
  if (!eroded.empty() && eroded[e]) {
    std::fill_n(f, 24, 0.0);
    stable[e] = std::numeric_limits<double>::infinity();
    return;
  }
  const Quad4& q = shells[e];
  std::array<Vec3, 4> p;
  for (int a = 0; a < 4; ++a) p[a] = {s.x[q[a]], s.y[q[a]], s.z[q[a]]};
  const Shell4Geometry g = shell4_geometry(p);
  if (!(g.area > 0.0)) {
    failure[e] = std::isfinite(g.area) ? kDegenerate : kNonFinite;
    return;
  }
  const bool triangle = is_triangle(q);
  const double h = section.thickness;
  const double area = g.area;

  // Local velocities; in-plane ones of the point where the node's fibre crosses the frame plane.
  double vx[4], vy[4], vz[4], tx[4], ty[4];
  for (int a = 0; a < 4; ++a) {
    const Vec3 v{s.vx[q[a]], s.vy[q[a]], s.vz[q[a]]};
    const Vec3 w{s.wx[q[a]], s.wy[q[a]], s.wz[q[a]]};
    tx[a] = dot(w, g.e1);
    ty[a] = dot(w, g.e2);
    vx[a] = dot(v, g.e1) - g.z[a] * ty[a];
    vy[a] = dot(v, g.e2) + g.z[a] * tx[a];
    vz[a] = dot(v, g.e3);
  }
  // Share of each node in the element mean of the rotations (the triangle's node 3 is two slots).
  const double share[4] = {triangle ? 1.0 / 3.0 : 0.25, triangle ? 1.0 / 3.0 : 0.25,
                           triangle ? 1.0 / 6.0 : 0.25, triangle ? 1.0 / 6.0 : 0.25};
  double dxx = 0, dyy = 0, gxy = 0, kxx = 0, kyy = 0, kxy = 0, gxz = 0, gyz = 0, vyx = 0, vxy = 0;
  for (int a = 0; a < 4; ++a) {
    dxx += g.b1[a] * vx[a];
    dyy += g.b2[a] * vy[a];
    vxy += g.b2[a] * vx[a];
    vyx += g.b1[a] * vy[a];
    kxx += g.b1[a] * ty[a];
    kyy -= g.b2[a] * tx[a];
    kxy += g.b2[a] * ty[a] - g.b1[a] * tx[a];
    gxz += g.b1[a] * vz[a] + share[a] * ty[a];
    gyz += g.b2[a] * vz[a] - share[a] * tx[a];
  }
  gxy = vxy + vyx;

  // The stored stress turns with the material spin about the normal minus the frame's own
  // (side 1-2 turns at (v_y2 - v_y1) / (x_2 - x_1)).
  Mat3 turn{1, 0, 0, 0, 1, 0, 0, 0, 1};
  if (dt > 0.0) {
    const double frame_spin = (vy[1] - vy[0]) / (g.x[1] - g.x[0]);
    const double angle = dt * (0.5 * (vyx - vxy) - frame_spin);
    const double c = std::cos(angle), sn = std::sin(angle);
    turn = {c, -sn, 0, sn, c, 0, 0, 0, 1};
  }

  const double ks = ShellSection::kShearFactor;
  double n[3] = {0, 0, 0}, m[3] = {0, 0, 0}, qs[2] = {0, 0};
  double work = 0.0;
  const std::size_t np = points();
  for (std::size_t k = 0; k < np; ++k) {
    const double zk = 0.5 * h * zeta[k];
    const double wk = 0.5 * h * weight[k];
    double* stored = &stress[6 * (np * e + k)];
    Sym3 now{{stored[0], stored[1], stored[2], stored[3], stored[4], stored[5]}};
    if (dt > 0.0) {
      const Sym3 old = rotate(turn, now);
      Sym3 increment{{dt * (dxx + zk * kxx), dt * (dyy + zk * kyy), 0.0,
                      0.5 * dt * (gxy + zk * kxy), 0.5 * dt * ks * gyz, 0.5 * dt * ks * gxz}};
      PointHistory none;
      now = history.empty() ? plane_stress_update(law, old, increment, dt, none)
                            : plane_stress_update(law, old, increment, dt, history[np * e + k],
                                                  &thickness_ratio[np * e + k]);
      // The transverse shear stress is k G gamma (the law saw k gamma); its power is tau gamma.
      Sym3 strain = increment;
      strain[4] = 0.5 * dt * gyz;
      strain[5] = 0.5 * dt * gxz;
      work += wk * 0.5 * double_dot(add(old, now), strain);
      std::copy(now.c.begin(), now.c.end(), stored);
    }
    n[0] += wk * now[0];
    n[1] += wk * now[1];
    n[2] += wk * now[3];
    m[0] += wk * zk * now[0];
    m[1] += wk * zk * now[1];
    m[2] += wk * zk * now[3];
    qs[0] += wk * now[5];  // Q = int tau dz = k G h gamma (elastic)
    qs[1] += wk * now[4];
  }
  internal_work[e] = area * work;

  // Internal forces conjugate to the local velocities (virtual power of N, M, Q).
  double fx[4], fy[4], fz[4], mx[4], my[4];
  for (int a = 0; a < 4; ++a) {
    fx[a] = area * (g.b1[a] * n[0] + g.b2[a] * n[2]);
    fy[a] = area * (g.b2[a] * n[1] + g.b1[a] * n[2]);
    fz[a] = area * (g.b1[a] * qs[0] + g.b2[a] * qs[1]);
    mx[a] = area * (-g.b2[a] * m[1] - g.b1[a] * m[2] - share[a] * qs[1]);
    my[a] = area * (g.b1[a] * m[0] + g.b2[a] * m[2] + share[a] * qs[0]);
  }
  // Hourglass resisting forces, stiffness form with the stiffnesses of Belytschko & Tsay (1983):
  // membrane c E h A (b.b) / 8, transverse c E h^3 (b.b) / 12, rotational c E h^3 A (b.b) / 192.
  if (!triangle && section.hourglass > 0.0) {
    double bb = 0.0, rate[5] = {0, 0, 0, 0, 0};
    for (int a = 0; a < 4; ++a) {
      bb += g.b1[a] * g.b1[a] + g.b2[a] * g.b2[a];
      rate[0] += g.gamma[a] * vx[a];
      rate[1] += g.gamma[a] * vy[a];
      rate[2] += g.gamma[a] * vz[a];
      rate[3] += g.gamma[a] * tx[a];
      rate[4] += g.gamma[a] * ty[a];
    }
    const double c = section.hourglass * young * bb;
    const double stiffness[5] = {c * h * area / 8.0, c * h * area / 8.0, c * h * h * h / 12.0,
                                 c * h * h * h * area / 192.0, c * h * h * h * area / 192.0};
    double* hg = &hourglass[5 * e];
    double hg_work = 0.0;
    for (int i = 0; i < 5; ++i) {
      const double before = hg[i];
      if (dt > 0.0) hg[i] += dt * stiffness[i] * rate[i];
      hg_work += dt * 0.5 * (before + hg[i]) * rate[i];
    }
    hourglass_work[e] = hg_work;
    for (int a = 0; a < 4; ++a) {
      fx[a] += g.gamma[a] * hg[0];
      fy[a] += g.gamma[a] * hg[1];
      fz[a] += g.gamma[a] * hg[2];
      mx[a] += g.gamma[a] * hg[3];
      my[a] += g.gamma[a] * hg[4];
    }
  }
  bool finite = true;
  for (int a = 0; a < 4; ++a) {
    // Back from the fibre points on the plane to the nodes (warping).
    mx[a] += g.z[a] * fy[a];
    my[a] -= g.z[a] * fx[a];
    const Vec3 force = -(fx[a] * g.e1 + fy[a] * g.e2 + fz[a] * g.e3);
    const Vec3 moment = -(mx[a] * g.e1 + my[a] * g.e2);
    double* fa = f + 6 * a;
    fa[0] = force.x;
    fa[1] = force.y;
    fa[2] = force.z;
    fa[3] = moment.x;
    fa[4] = moment.y;
    fa[5] = moment.z;
    finite = finite && std::isfinite(force.x + force.y + force.z + moment.x + moment.y + moment.z);
  }
  failure[e] = finite ? kOk : kNonFinite;
  stable[e] = shell4_critical_length(g, triangle) / wave_speed;
  if (!eroded.empty()) {
    area_ratio[e] = area / reference_area[e];
    if (erosion.max_geometric_strain < 1e20)
      geometric_strain[e] = membrane_log_strain(g, &reference_b[8 * e]);
  }
}

template <class Law>
BlockStep ShellBlock::Impl::step(const ShellNodalState& s, double dt, const Law& law) {
  const auto count = static_cast<std::int64_t>(shells.size());
#pragma omp parallel for schedule(static) if (count >= kParallelMinimum / 8)
  for (std::int64_t e = 0; e < count; ++e) element(static_cast<std::size_t>(e), s, dt, law);

  static_assert(kDegenerate == 1 && kNonFinite == 2, "the messages below, by failure code");
  return end_block_step(
      *this, shells.size(),
      {nullptr, ": collapsed element (area <= 0)", ": non-finite area, stress or force"});
}

// As SolidBlock: a shell fails by damage once all of its points have failed.
void ShellBlock::Impl::erode(BlockStep& out) {
  const std::size_t np = points();
  erode_elements(
      *this, shells.size(), 24, out,
      [this, np](std::size_t e) {
        bool all_failed = fails_by_damage;
        for (std::size_t k = 0; k < np && all_failed; ++k)
          all_failed = history[np * e + k].failed();
        return stable[e] < erosion.min_step || geometric_strain[e] > erosion.max_geometric_strain ||
               area_ratio[e] - 1.0 > erosion.max_volumetric_strain || all_failed;
      },
      [this, np](std::size_t e) { std::fill_n(&stress[6 * np * e], 6 * np, 0.0); });
}

ShellBlock::ShellBlock(std::int64_t part_id, const MaterialParams& material,
                       const ShellSection& section, std::vector<Quad4> shells,
                       const Nodes& reference, const FunctionTable* functions)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.part_id = part_id;
  m.material = material;
  m.section = section;
  m.shells = std::move(shells);
  m.functions = functions;
  if (const auto* p = std::get_if<ElasticParams>(&material)) {
    m.density = p->density, m.young = p->young, m.poisson = p->poisson;
  } else if (const auto* metal = std::get_if<MetalParams>(&material)) {
    m.density = metal->density, m.young = metal->young, m.poisson = metal->poisson;
    if (!metal->johnson_cook && functions == nullptr)
      throw InputError(part_prefix(part_id) +
                       "the flow curve of *MAT_METAL needs the deck's "
                       "functions");
  } else {
    throw InputError(part_prefix(part_id) +
                     "shells take *MAT_ELASTIC, *MAT_METAL or *MAT_JC (or *MAT_RIGID for a rigid "
                     "part); other materials on shells are not supported yet");
  }
  if (!(m.density > 0.0) || !(m.young > 0.0) || !(m.poisson > -1.0 && m.poisson < 0.5))
    throw InputError(part_prefix(part_id) + "shell material needs rho > 0, E > 0, -1 < nu < 0.5");
  if (!(section.thickness > 0.0))
    throw InputError(part_prefix(part_id) + "shell thickness h must be > 0");
  if (section.points < 1 || section.points % 2 == 0)
    throw InputError(part_prefix(part_id) + "expected an odd number of thickness points");
  m.lame = {m.young * m.poisson / ((1.0 + m.poisson) * (1.0 - 2.0 * m.poisson)),
            m.young / (2.0 * (1.0 + m.poisson))};
  m.wave_speed = std::sqrt(m.young / (m.density * (1.0 - m.poisson * m.poisson)));
  gauss_legendre(section.points, m.zeta, m.weight);

  const std::size_t n = m.shells.size();
  m.reference_area.resize(n);
  m.reference_b.resize(8 * n);
  for (std::size_t e = 0; e < n; ++e) {
    std::array<Vec3, 4> p;
    for (int a = 0; a < 4; ++a) {
      const std::int32_t node = m.shells[e][a];
      if (node < 0 || static_cast<std::size_t>(node) >= reference.size())
        throw InputError(m.element_name(e) + ": node index outside the node list");
      p[a] = reference.position(static_cast<std::size_t>(node));
    }
    const Shell4Geometry g = shell4_geometry(p);
    if (!(g.area > 0.0))
      throw InputError(m.element_name(e) + ": zero area in the initial configuration");
    m.reference_area[e] = g.area;
    std::copy(g.b1.begin(), g.b1.end(), &m.reference_b[8 * e]);
    std::copy(g.b2.begin(), g.b2.end(), &m.reference_b[8 * e + 4]);
  }
  const std::size_t np = m.points();
  m.stress.assign(6 * np * n, 0.0);
  if (const auto* metal = std::get_if<MetalParams>(&material)) {
    m.history.assign(np * n, {});
    m.thickness_ratio.assign(np * n, -m.poisson / (1.0 - m.poisson));
    m.fails_by_damage = metal->failure.active;
  }
  m.hourglass.assign(5 * n, 0.0);
  m.forces.assign(24 * n, 0.0);
  m.internal_work.assign(n, 0.0);
  m.hourglass_work.assign(n, 0.0);
  m.stable.assign(n, 0.0);
  m.failure.assign(n, kOk);
}

ShellBlock::~ShellBlock() = default;
ShellBlock::ShellBlock(ShellBlock&&) noexcept = default;
ShellBlock& ShellBlock::operator=(ShellBlock&&) noexcept = default;

std::int64_t ShellBlock::part_id() const { return impl_->part_id; }
const std::vector<Quad4>& ShellBlock::shells() const { return impl_->shells; }
std::size_t ShellBlock::size() const { return impl_->shells.size(); }
const ShellSection& ShellBlock::section() const { return impl_->section; }
const std::vector<double>& ShellBlock::element_forces() const { return impl_->forces; }
const std::vector<double>& ShellBlock::point_stress() const { return impl_->stress; }
const std::vector<std::uint8_t>& ShellBlock::eroded() const { return impl_->eroded; }
// Everything update() carries from one step to the next (SolidBlock::archive).
void ShellBlock::archive(StateArchive& a) {
  Impl& m = *impl_;
  a.mark("shell block");
  a.expect(m.part_id, "the part of a shell block");
  a.expect(static_cast<std::uint64_t>(m.shells.size()), "the element count of a shell block");
  a.fixed(m.stress, m.history, m.thickness_ratio, m.hourglass, m.forces, m.internal_work,
          m.hourglass_work, m.stable, m.failure, m.eroded, m.element_internal, m.element_hourglass,
          m.geometric_strain, m.area_ratio);
  a.values(m.internal_energy, m.hourglass_energy, m.eroded_energy, m.eroded_count);
}

void ShellBlock::set_element_ids(std::vector<std::int64_t> ids) {
  impl_->element_ids = std::move(ids);
}

void ShellBlock::add_lumped_mass(std::vector<double>& nodal_mass,
                                 std::vector<double>& rotary_inertia) const {
  const Impl& m = *impl_;
  const double h = m.section.thickness;
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    const bool triangle = is_triangle(m.shells[e]);
    const double area = m.reference_area[e];
    const double share = m.density * h * area / (triangle ? 3.0 : 4.0);
    const double inertia = share * (h * h + area) / 12.0;
    for (int a = 0; a < (triangle ? 3 : 4); ++a) {
      const auto node = static_cast<std::size_t>(m.shells[e][a]);
      nodal_mass[node] += share;
      rotary_inertia[node] += inertia;
    }
  }
}

double ShellBlock::initial_stable_step(const Nodes& reference) const {
  double step = std::numeric_limits<double>::infinity();
  for (const Quad4& q : impl_->shells) {
    std::array<Vec3, 4> p;
    for (int a = 0; a < 4; ++a) p[a] = reference.position(static_cast<std::size_t>(q[a]));
    step = std::min(step,
                    shell4_critical_length(shell4_geometry(p), is_triangle(q)) / impl_->wave_speed);
  }
  return step;
}

BlockStep ShellBlock::update(const ShellNodalState& state, double dt) {
  if (!(dt >= 0.0) || !std::isfinite(dt))
    throw InstabilityError(part_prefix(impl_->part_id) + "time step must be finite and >= 0");
  Impl& m = *impl_;
  if (const auto* metal = std::get_if<MetalParams>(&m.material))
    return m.step(state, dt, MetalPoint{m.lame, FlowStress(*metal, m.functions), metal->failure});
  return m.step(state, dt, ElasticPoint{m.lame});
}

void ShellBlock::von_mises_stress(std::vector<double>& out) const {
  const Impl& m = *impl_;
  const std::size_t np = m.points();
  out.assign(m.shells.size(), 0.0);
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    for (std::size_t k = 0; k < np; ++k) {
      const double* s = &m.stress[6 * (np * e + k)];
      out[e] = std::max(out[e], von_mises({{s[0], s[1], s[2], s[3], s[4], s[5]}}));
    }
  }
}

void ShellBlock::plastic_strain(std::vector<double>& out) const {
  const Impl& m = *impl_;
  const std::size_t np = m.points();
  out.assign(m.shells.size(), 0.0);
  if (m.history.empty()) return;
  for (std::size_t e = 0; e < m.shells.size(); ++e)
    for (std::size_t k = 0; k < np; ++k)
      out[e] = std::max(out[e], m.history[np * e + k].plastic_strain);
}

void ShellBlock::plastic_strain_rate(std::vector<double>& out) const {
  const Impl& m = *impl_;
  const std::size_t np = m.points();
  out.assign(m.shells.size(), 0.0);
  if (m.history.empty()) return;
  for (std::size_t e = 0; e < m.shells.size(); ++e)
    for (std::size_t k = 0; k < np; ++k)
      out[e] = std::max(out[e], m.history[np * e + k].plastic_strain_rate);
}

void ShellBlock::resultants(std::size_t e, double n[3], double mm[3], double q[2]) const {
  const Impl& m = *impl_;
  const std::size_t np = m.points();
  const double h = m.section.thickness;
  for (int i = 0; i < 3; ++i) n[i] = mm[i] = 0.0;
  q[0] = q[1] = 0.0;
  for (std::size_t k = 0; k < np; ++k) {
    const double* s = &m.stress[6 * (np * e + k)];
    const double wk = 0.5 * h * m.weight[k], zk = 0.5 * h * m.zeta[k];
    const double in_plane[3] = {s[0], s[1], s[3]};
    for (int i = 0; i < 3; ++i) {
      n[i] += wk * in_plane[i];
      mm[i] += wk * zk * in_plane[i];
    }
    q[0] += wk * s[5];
    q[1] += wk * s[4];
  }
}

void ShellBlock::set_erosion(const ErosionCriteria& criteria) {
  Impl& m = *impl_;
  m.erosion = criteria;
  if (!criteria.any() && !m.fails_by_damage) return;
  const std::size_t n = m.shells.size();
  m.eroded.assign(n, 0);
  m.element_internal.assign(n, 0.0);
  m.element_hourglass.assign(n, 0.0);
  m.geometric_strain.assign(n, 0.0);
  m.area_ratio.assign(n, 1.0);
}

}  // namespace abut
