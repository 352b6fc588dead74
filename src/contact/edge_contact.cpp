// Edge-to-edge contact: broad phase over edge boxes, closest points of crossing segments, a
// penalty spring along their common normal with the side remembered per pair (edge_contact.hpp).
#include "abut/contact/edge_contact.hpp"

#include <algorithm>
#include <cmath>

#include "abut/core/parallel.hpp"
#include "abut/core/vec3.hpp"

namespace abut {
namespace {

// Pairs whose directions differ by less than this sine are left to the point-to-facet contact.
constexpr double kParallelSine = 1e-2;

Vec3 at(std::span<const double> x, std::span<const double> y, std::span<const double> z,
        std::int32_t i) {
  return {x[i], y[i], z[i]};
}

struct Closest {
  double s = 0.0, t = 0.0;
};

// Closest points of segments p1 + s d1 and p2 + t d2, s, t in [0, 1] (Ericson 2005, 5.1.9), for
// segments of non-zero length.
Closest closest_points(const Vec3& p1, const Vec3& d1, const Vec3& p2, const Vec3& d2) {
  const Vec3 r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  const double c = dot(d1, r), b = dot(d1, d2), denom = a * e - b * b;
  Closest q;
  q.s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  q.t = (b * q.s + f) / e;
  if (q.t < 0.0) {
    q.t = 0.0;
    q.s = std::clamp(-c / a, 0.0, 1.0);
  } else if (q.t > 1.0) {
    q.t = 1.0;
    q.s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return q;
}

}  // namespace

EdgeContact::EdgeContact(ContactEdges edges1, ContactEdges edges2, bool self, double damping,
                         double margin)
    : first_(std::move(edges1)),
      second_(std::move(edges2)),
      self_(self),
      damping_(damping),
      margin_(margin) {
  hits_.resize(first_.size());
  previous_.resize(first_.size());
  partial_.resize(first_.size());
}

void EdgeContact::rebuild(std::span<const double> x, std::span<const double> y,
                          std::span<const double> z) {
  const ContactEdges& second = self_ ? first_ : second_;
  double reach1 = 0.0;  // the largest radius and half length of the first edges
  mx_.resize(first_.size());
  my_.resize(first_.size());
  mz_.resize(first_.size());
  for (std::size_t i = 0; i < first_.size(); ++i) {
    const Vec3 a = at(x, y, z, first_.nodes[i][0]), b = at(x, y, z, first_.nodes[i][1]);
    const Vec3 m = (a + b) * 0.5;
    mx_[i] = m.x;
    my_[i] = m.y;
    mz_[i] = m.z;
    reach1 = std::max(reach1, first_.radius[i] + 0.5 * norm(b - a));
  }
  std::vector<Box> boxes(second.size());
  for (std::size_t j = 0; j < second.size(); ++j) {
    const Vec3 a = at(x, y, z, second.nodes[j][0]), b = at(x, y, z, second.nodes[j][1]);
    const double grow = second.radius[j] + reach1 + margin_;
    for (int k = 0; k < 3; ++k) {
      boxes[j].lo[k] = std::min(a[k], b[k]) - grow;
      boxes[j].hi[k] = std::max(a[k], b[k]) + grow;
    }
  }
  grid_.build(boxes);
  const auto keep = [this, &second](std::size_t i, std::int32_t j) {
    if (self_ && j <= static_cast<std::int32_t>(i)) return false;  // each pair once
    const auto& e1 = first_.nodes[i];
    const auto& e2 = second.nodes[static_cast<std::size_t>(j)];
    return e1[0] != e2[0] && e1[0] != e2[1] && e1[1] != e2[0] && e1[1] != e2[1];
  };
  grid_.query(mx_, my_, mz_, candidates_, keep);
}

EdgeContactResult EdgeContact::apply(std::span<const double> x, std::span<const double> y,
                                     std::span<const double> z, std::span<const double> vx,
                                     std::span<const double> vy, std::span<const double> vz,
                                     std::span<const double> mass, std::span<double> fx,
                                     std::span<double> fy, std::span<double> fz,
                                     std::span<double> dx, std::span<double> dy,
                                     std::span<double> dz) {
  if (candidates_.point_count() != first_.size()) rebuild(x, y, z);
  const ContactEdges& second = self_ ? first_ : second_;
  std::swap(hits_, previous_);
  const std::size_t n = first_.size();
#pragma omp parallel for schedule(dynamic, \
                                  256) if (n >= static_cast <std::size_t>(kParallelMinimum))
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Hit>& hits = hits_[i];
    hits.clear();
    EdgeContactResult& r = partial_[i];
    r = {};
    const auto [a1, b1] = first_.nodes[i];
    const Vec3 p1 = at(x, y, z, a1), d1 = at(x, y, z, b1) - p1;
    for (std::size_t k = candidates_.offsets[i]; k < candidates_.offsets[i + 1]; ++k) {
      const std::int32_t j = candidates_.facets[k];
      const auto [a2, b2] = second.nodes[static_cast<std::size_t>(j)];
      const Vec3 p2 = at(x, y, z, a2), d2 = at(x, y, z, b2) - p2;
      const Vec3 normal = cross(d1, d2);
      const double sine = norm(normal);
      if (!(sine > kParallelSine * norm(d1) * norm(d2))) continue;
      const Closest q = closest_points(p1, d1, p2, d2);
      if (q.s <= 0.0 || q.s >= 1.0 || q.t <= 0.0 || q.t >= 1.0) continue;  // ends: node contact
      const Vec3 c = normal / sine;
      const Vec3 gap = p1 + d1 * q.s - (p2 + d2 * q.t);
      const double reach = first_.radius[i] + second.radius[static_cast<std::size_t>(j)];
      const double along = dot(c, gap);
      if (std::abs(along) > reach + margin_) continue;
      Hit h;
      h.other = j;
      h.s = q.s;
      h.t = q.t;
      h.side = along >= 0.0 ? 1 : -1;
      for (const Hit& old : previous_[i])  // the side it came from
        if (old.other == j) h.side = old.side;
      const Vec3 push = c * static_cast<double>(h.side);
      const double penetration = reach - dot(push, gap);
      if (penetration > 0.0) {
        const double spring =
            std::min(first_.stiffness[i], second.stiffness[static_cast<std::size_t>(j)]);
        const double m1 = mass[a1] * (1.0 - q.s) + mass[b1] * q.s;
        const double m2 = mass[a2] * (1.0 - q.t) + mass[b2] * q.t;
        const double m = m1 + m2 > 0.0 ? m1 * m2 / (m1 + m2) : 0.0;
        const Vec3 v1 = at(vx, vy, vz, a1) * (1.0 - q.s) + at(vx, vy, vz, b1) * q.s;
        const Vec3 v2 = at(vx, vy, vz, a2) * (1.0 - q.t) + at(vx, vy, vz, b2) * q.t;
        const double v_n = dot(v1 - v2, push);  // < 0 while approaching
        const double c_d = 2.0 * damping_ * std::sqrt(spring * m);
        const double elastic = spring * penetration;
        const double f = std::max(elastic - c_d * v_n, 0.0);
        h.force = f;
        h.damping = f - elastic;
        h.direction = {push.x, push.y, push.z};
        r.elastic_energy += 0.5 * spring * penetration * penetration;
        r.normal_force += f;
        r.max_penetration = std::max(r.max_penetration, penetration);
        if (m > 0.0) r.omega2 = std::max(r.omega2, spring / m);
        ++r.active_pairs;
      }
      hits.push_back(h);
    }
  }
  // Serially, in edge order: sums independent of the thread count.
  EdgeContactResult total;
  for (std::size_t i = 0; i < n; ++i) {
    const auto [a1, b1] = first_.nodes[i];
    for (const Hit& h : hits_[i]) {
      if (h.force == 0.0) continue;
      const auto [a2, b2] = second.nodes[static_cast<std::size_t>(h.other)];
      const double f[3] = {h.force * h.direction[0], h.force * h.direction[1],
                           h.force * h.direction[2]};
      const std::int32_t nodes[4] = {a1, b1, a2, b2};
      const double w[4] = {1.0 - h.s, h.s, -(1.0 - h.t), -h.t};
      for (int k = 0; k < 3; ++k) total.force_on_first[k] += f[k];
      for (int a = 0; a < 4; ++a) {
        fx[nodes[a]] += w[a] * f[0];
        fy[nodes[a]] += w[a] * f[1];
        fz[nodes[a]] += w[a] * f[2];
        dx[nodes[a]] += w[a] * h.damping * h.direction[0];
        dy[nodes[a]] += w[a] * h.damping * h.direction[1];
        dz[nodes[a]] += w[a] * h.damping * h.direction[2];
      }
    }
    const EdgeContactResult& r = partial_[i];
    total.elastic_energy += r.elastic_energy;
    total.normal_force += r.normal_force;
    total.max_penetration = std::max(total.max_penetration, r.max_penetration);
    total.omega2 = std::max(total.omega2, r.omega2);
    total.active_pairs += r.active_pairs;
  }
  return total;
}

}  // namespace abut
