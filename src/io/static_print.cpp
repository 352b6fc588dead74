#include "io/static_print.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace abut {

namespace {

// CalculiX writes the time as a Fortran E14.7 (0.1000000E+01); any float format parses the same.
std::string time_text(double t) { return fmt::format("{:14.7E}", t); }

std::string set_text(const PrintRequest& r) {
  std::string s = r.set_name;
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

bool wants(const PrintRequest& r, const char* quantity) {
  return std::find(r.quantities.begin(), r.quantities.end(), quantity) != r.quantities.end();
}

std::vector<std::int32_t> members_or_all(const PrintRequest& r, std::size_t all) {
  if (!r.members.empty()) return r.members;
  std::vector<std::int32_t> out(all);
  for (std::size_t i = 0; i < all; ++i) out[i] = static_cast<std::int32_t>(i);
  return out;
}

// A contact point's tangent basis, as CalculiX prints tangential values: tang1 along the
// projection of the global x axis (y if the normal is along x), tang2 = n x tang1.
void tangent_basis(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Vec3 axis = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  t1 = normalized(axis - n * dot(axis, n));
  t2 = cross(n, t1);
}

// The solid and its face (S number) of a secondary facet, for surface-to-surface rows: the face
// that holds all of the facet's nodes (a facet of a quadratic face holds some of them).
void element_face(const Model& model, const ContactSurface& s, std::int32_t facet,
                  std::int64_t& element, int& face) {
  const std::int32_t solid = s.element[static_cast<std::size_t>(facet)];
  element = 0;
  face = 0;
  if (solid < 0 || static_cast<std::size_t>(solid) >= model.mesh.solid_count()) return;
  const SolidRef cell = model.mesh.solid(static_cast<std::size_t>(solid));
  element = cell.id;
  const auto& faces = topology(cell.type).faces;
  for (std::size_t f = 0; f < faces.size() && face == 0; ++f) {
    bool all = true;
    for (const std::int32_t n : s.facets[static_cast<std::size_t>(facet)]) {
      bool on_face = false;
      for (int a = 0; a < faces[f].size(); ++a)
        on_face = on_face || cell.nodes[static_cast<std::size_t>(faces[f].nodes[a])] == n;
      all = all && on_face;
    }
    if (all) face = static_cast<int>(f) + 1;
  }
}

void print_nodes(std::ostream& out, const Model& model, const PrintRequest& r,
                 const StaticSolver& solver, double t) {
  const std::vector<std::int32_t> nodes = members_or_all(r, model.mesh.nodes.size());
  auto block = [&](const char* title, std::span<const double> v) {
    if (r.totals_only) return;
    out << fmt::format("\n {} for set {} and time {}\n\n", title, set_text(r), time_text(t));
    for (const std::int32_t n : nodes)
      out << fmt::format("{:10d}{:14.6E}{:14.6E}{:14.6E}\n", model.mesh.nodes.id[n], v[3 * n],
                         v[3 * n + 1], v[3 * n + 2]);
  };
  if (wants(r, "U")) block("displacements (vx,vy,vz)", solver.displacement());
  if (wants(r, "RF")) {
    block("forces (fx,fy,fz)", solver.nodal_force());
    if (r.totals || r.totals_only) {  // TOTALS=YES/ONLY: the sum over the set (CalculiX's line)
      double sum[3] = {0.0, 0.0, 0.0};
      for (const std::int32_t n : nodes)
        for (int k = 0; k < 3; ++k) sum[k] += solver.nodal_force()[3 * n + k];
      out << fmt::format(
          "\n total force (fx,fy,fz) for set {} and time {}\n\n{:20.6E}{:14.6E}{:14.6E}\n",
          set_text(r), time_text(t), sum[0], sum[1], sum[2]);
    }
  }
}

void print_elements(std::ostream& out, const Model& model, const PrintRequest& r,
                    const StaticSolver& solver, double t) {
  const std::vector<std::int32_t> elements = members_or_all(r, model.mesh.solid_count());
  const auto id = [&](std::int32_t e) { return model.mesh.solid(static_cast<std::size_t>(e)).id; };
  const auto point = [&](std::int32_t e, int p) {
    return solver.first_point(static_cast<std::size_t>(e)) + static_cast<std::size_t>(p);
  };
  // Our Voigt order xx yy zz xy yz zx; CalculiX prints xx yy zz xy xz yz.
  static constexpr int kOrder[6] = {0, 1, 2, 3, 5, 4};
  auto tensor_block = [&](const char* title, std::span<const double> v, double shear) {
    out << fmt::format("\n {} for set {} and time {}\n\n", title, set_text(r), time_text(t));
    for (const std::int32_t h : elements)
      for (int p = 0; p < solver.integration_points(static_cast<std::size_t>(h)); ++p) {
        out << fmt::format("{:10d}{:4d}", id(h), p + 1);
        for (int k = 0; k < 6; ++k)
          out << fmt::format("{:14.6E}", v[6 * point(h, p) + kOrder[k]] * (k >= 3 ? shear : 1.0));
        out << "\n";
      }
  };
  if (wants(r, "S") && !r.totals_only)
    tensor_block("stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz)", solver.stress(), 1.0);
  if (wants(r, "E") && !r.totals_only)  // tensor shears, as CalculiX prints them
    tensor_block("strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)", solver.strain(), 0.5);
  // Mechanical strains: the total strain less the thermal one, which abut does not have.
  if (wants(r, "ME") && !r.totals_only)
    tensor_block("mechanical strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)", solver.strain(),
                 0.5);
  // Scalars per integration point, with CalculiX 2.20's titles (PEEQ's has no space before
  // "for").
  auto point_block = [&](const char* title, std::span<const double> v) {
    out << fmt::format("\n {}set {} and time {}\n\n", title, set_text(r), time_text(t));
    for (const std::int32_t h : elements)
      for (int p = 0; p < solver.integration_points(static_cast<std::size_t>(h)); ++p)
        out << fmt::format("{:10d}{:4d}{:14.6E}\n", id(h), p + 1, v[point(h, p)]);
  };
  if (wants(r, "ENER") && !r.totals_only)
    point_block("internal energy density (elem, integ.pnt.,energy) for ", solver.energy_density());
  if (wants(r, "PEEQ") && !r.totals_only)
    point_block("equivalent plastic strain (elem, integ.pnt.,pe)for ", solver.plastic_strain());
  if (wants(r, "EVOL")) {
    double total = 0.0;
    for (const std::int32_t h : elements) total += solver.element_volume()[h];
    if (!r.totals_only) {
      out << fmt::format("\n volume (element, volume) for set {} and time {}\n\n", set_text(r),
                         time_text(t));
      for (const std::int32_t h : elements)
        out << fmt::format("{:10d}{:14.6E}\n", id(h), solver.element_volume()[h]);
    }
    if (r.totals || r.totals_only)
      out << fmt::format("\n total volume for set {} and time {}\n\n{:20.6E}\n", set_text(r),
                         time_text(t), total);
  }
  if (wants(r, "ELSE")) {
    double total = 0.0;
    for (const std::int32_t h : elements) total += solver.element_energy()[h];
    if (!r.totals_only) {
      out << fmt::format("\n internal energy (element, energy) for set {} and time {}\n\n",
                         set_text(r), time_text(t));
      for (const std::int32_t h : elements)
        out << fmt::format("{:10d}{:14.6E}\n", id(h), solver.element_energy()[h]);
    }
    if (r.totals || r.totals_only)
      out << fmt::format("\n total internal energy for set {} and time {}\n\n{:20.6E}\n",
                         set_text(r), time_text(t), total);
  }
}

void print_contact(std::ostream& out, const Model& model, const PrintRequest& r,
                   const StaticSolver& solver, double t) {
  std::vector<std::uint8_t> in_set;
  if (!r.members.empty()) {
    in_set.assign(model.mesh.nodes.size(), 0);
    for (const std::int32_t n : r.members) in_set[n] = 1;
  }
  double total_energy = 0.0;
  for (const StaticContact& c : solver.contacts()) {
    const char* who = c.node_to_surface() ? "slave node" : "slave element+face";
    auto row_start = [&](const StaticContactPoint& p) {
      if (p.node >= 0) return fmt::format("{:10d}", model.mesh.nodes.id[p.node]);
      std::int64_t element = 0;
      int face = 0;
      element_face(model, c.secondary(), p.facet, element, face);
      return fmt::format("{:10d}{:11d}", element, face);
    };
    auto selected = [&](const StaticContactPoint& p) {
      return p.active && (in_set.empty() || (p.node >= 0 && in_set[p.node]));
    };
    for (const StaticContactPoint& p : c.points())
      if (selected(p)) total_energy += p.energy;
    if (r.totals_only) continue;
    auto point_rows = [&](const std::string& header, auto values) {
      out << fmt::format("\n {} for all contact elements and time {}\n\n", header, time_text(t));
      for (const StaticContactPoint& p : c.points()) {
        if (!selected(p)) continue;
        Vec3 t1, t2;
        tangent_basis(p.normal, t1, t2);
        const auto [n, v] = values(p);
        out << row_start(p) << fmt::format("{:14.6E}{:14.6E}{:14.6E}\n", n, dot(v, t1), dot(v, t2));
      }
    };
    // CSTR: the tangential traction the slave exerts on the master (along its slip), which is
    // CalculiX's sign; the pressure is the same on either side.
    if (wants(r, "CSTR"))
      point_rows(fmt::format("contact stress ({},press,tang1,tang2)", who),
                 [](const StaticContactPoint& p) {
                   return std::pair{p.pressure, -p.traction};
                 });
    if (wants(r, "CDIS"))
      point_rows(fmt::format("relative contact displacement ({},normal,tang1,tang2)", who),
                 [](const StaticContactPoint& p) {
                   return std::pair{p.gap, p.total_slip};
                 });
    if (wants(r, "CELS")) {
      out << fmt::format(
          "\n contact print energy ({},energy)for all contact elements and time "
          "{}\n",
          who, time_text(t));
      for (const StaticContactPoint& p : c.points())
        if (selected(p)) out << row_start(p) << fmt::format("{:14.6E}\n", p.energy);
    }
  }
  if (wants(r, "CELS") && (r.totals || r.totals_only))
    out << fmt::format("\n total contact spring energy for time {}\n\n{:20.6E}\n", time_text(t),
                       total_energy);
}

}  // namespace

void print_static_results(std::ostream& out, const Model& model, const StaticStep& step,
                          const StaticSolver& solver, const StaticIncrement& increment) {
  for (const PrintRequest& r : step.prints) {
    const bool due =
        increment.step_end || (r.frequency > 0 && increment.increment % r.frequency == 0);
    if (!due) continue;
    switch (r.kind) {
      case PrintRequest::Kind::Node:
        print_nodes(out, model, r, solver, increment.total_time);
        break;
      case PrintRequest::Kind::Element:
        print_elements(out, model, r, solver, increment.total_time);
        break;
      case PrintRequest::Kind::Contact:
        print_contact(out, model, r, solver, increment.total_time);
        break;
    }
  }
}

}  // namespace abut
