// TEMPORARY stand-ins so that the deck reader builds and its tests run before the real mesh
// generators, refinement, geometry test and FunctionTable land from other branches.
// DELETE THIS FILE WHEN MERGING those implementations. Nothing here is meant to be right
// beyond what the deck tests need: the box generator is exact, the sphere and cylinder are
// crude boxes, refinement does nothing, functions evaluate plain numbers only.
#include <algorithm>
#include <cstdlib>
#include <map>

#include "abut/core/functions.hpp"
#include "abut/mesh/generators.hpp"
#include "abut/mesh/geometry.hpp"
#include "abut/mesh/refine.hpp"

namespace abut {

void generate_box(Mesh& mesh, const BoxComponent& c) {
  if (c.nx < 1 || c.ny < 1 || c.nz < 1) throw InputError("element counts must be >= 1");
  std::int64_t node_id = mesh.next_node_id();
  std::int64_t hex_id = mesh.next_hex_id();
  const auto first = static_cast<std::int32_t>(mesh.nodes.size());
  const auto at = [&](int i, int j, int k) {
    return first + i + (c.nx + 1) * (j + (c.ny + 1) * k);
  };
  for (int k = 0; k <= c.nz; ++k) {
    for (int j = 0; j <= c.ny; ++j) {
      for (int i = 0; i <= c.nx; ++i) {
        const Vec3 t{double(i) / c.nx, double(j) / c.ny, double(k) / c.nz};
        mesh.nodes.add(node_id++, {c.corner1.x + t.x * (c.corner2.x - c.corner1.x),
                                   c.corner1.y + t.y * (c.corner2.y - c.corner1.y),
                                   c.corner1.z + t.z * (c.corner2.z - c.corner1.z)});
      }
    }
  }
  for (int k = 0; k < c.nz; ++k) {
    for (int j = 0; j < c.ny; ++j) {
      for (int i = 0; i < c.nx; ++i) {
        mesh.hexes.push_back({at(i, j, k), at(i + 1, j, k), at(i + 1, j + 1, k), at(i, j + 1, k),
                              at(i, j, k + 1), at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1),
                              at(i, j + 1, k + 1)});
        mesh.hex_id.push_back(hex_id++);
        mesh.hex_part.push_back(c.part_id);
        mesh.hex_shape.push_back(-1);
      }
    }
  }
}

void generate_sphere(Mesh& mesh, const SphereComponent& c) {
  const double h = c.outer_radius / std::sqrt(3.0);
  generate_box(mesh, {c.part_id, c.density, c.density, c.density, c.centre - Vec3{h, h, h},
                      c.centre + Vec3{h, h, h}});
}

void generate_cylinder(Mesh& mesh, const CylinderComponent& c) {
  const double r = std::max(c.radius1, c.radius2);
  Vec3 lo, hi;
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(c.end1[k], c.end2[k]) - r;
    hi[k] = std::max(c.end1[k], c.end2[k]) + r;
  }
  generate_box(mesh, {c.part_id, c.n_axial, c.density, c.density, lo, hi});
}

std::vector<std::string> refine_and_smooth(Mesh&, const std::vector<OrderChange>& orders,
                                           const std::vector<SurfaceSmoothing>& smoothing) {
  std::vector<std::string> notes;
  for (const auto& o : orders)
    notes.push_back("stand-in: order " + std::to_string(o.order) + " not applied");
  for (const auto& s : smoothing)
    notes.push_back("stand-in: smoothing " + std::to_string(s.max_angle) + " not applied");
  return notes;
}

bool geometry_contains(const Geometry& g, const Vec3& p, const Mesh&) {
  if (const auto* b = std::get_if<GeometryBox>(&g)) {
    for (int k = 0; k < 3; ++k) {
      if (p[k] < std::min(b->corner1[k], b->corner2[k]) ||
          p[k] > std::max(b->corner1[k], b->corner2[k]))
        return false;
    }
    return true;
  }
  throw InputError("stand-in geometry_contains handles boxes only");
}

double Curve::value(double at) const {
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
  return y[i - 1] + (y[i] - y[i - 1]) * (at - x[i - 1]) / (x[i] - x[i - 1]);
}

struct FunctionTable::Impl {
  struct Entry {
    std::int64_t id;
    bool curve;
    Curve values;
    std::string expression;
  };
  std::vector<Entry> entries;
  std::map<std::int64_t, std::int32_t> index;
  void add(Entry e, const SourceLocation& where) {
    if (index.count(e.id))
      throw InputError(where, "id " + std::to_string(e.id) + " is already used");
    index[e.id] = static_cast<std::int32_t>(entries.size());
    entries.push_back(std::move(e));
  }
};

FunctionTable::FunctionTable() : impl_(std::make_unique<Impl>()) {}
FunctionTable::~FunctionTable() = default;
FunctionTable::FunctionTable(FunctionTable&&) noexcept = default;
FunctionTable& FunctionTable::operator=(FunctionTable&&) noexcept = default;

void FunctionTable::add_curve(std::int64_t id, Curve curve, const SourceLocation& where) {
  impl_->add({id, true, std::move(curve), ""}, where);
}
void FunctionTable::add_function(std::int64_t id, const std::string& expression,
                                 const SourceLocation& where) {
  impl_->add({id, false, {}, expression}, where);
}
void FunctionTable::resolve() {}
bool FunctionTable::contains(std::int64_t id) const { return impl_->index.count(id) > 0; }
FunctionRef FunctionTable::find(std::int64_t id, const SourceLocation& where) const {
  const auto it = impl_->index.find(id);
  if (it == impl_->index.end())
    throw InputError(where, "curve or function " + std::to_string(id) + " does not exist");
  return {it->second};
}
bool FunctionTable::is_curve(FunctionRef ref) const {
  return impl_->entries[static_cast<std::size_t>(ref.index)].curve;
}
bool FunctionTable::uses(FunctionRef, const std::string&) const { return false; }
double FunctionTable::value(FunctionRef ref, double abscissa, const Variables&) const {
  const auto& e = impl_->entries[static_cast<std::size_t>(ref.index)];
  if (e.curve) return e.values.value(abscissa);
  return evaluate_constant_expression(e.expression);
}

double evaluate_constant_expression(const std::string& expression) {
  const char* begin = expression.c_str();
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  while (end && (*end == ' ' || *end == '\t')) ++end;
  if (end == begin || *end != '\0')
    throw InputError("stand-in evaluator reads plain numbers only: '" + expression + "'");
  return v;
}

}  // namespace abut
