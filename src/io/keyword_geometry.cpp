// *GEOMETRY_BOX, *GEOMETRY_SPHERE, *GEOMETRY_PIPE, *GEOMETRY_ELLIPSOID, *GEOMETRY_PART.
#include <algorithm>
#include <cmath>

#include "deck_reader.hpp"

namespace abut::deck {
namespace {

Vec3 point(const Row& r, std::size_t first) {
  return {r.number(first), r.number(first + 1), r.number(first + 2)};
}

// Title line and `gid, csysid`; returns the entry to fill.
GeometryEntry head(DeckReader& d, Block& b, bool has_csysid) {
  b.title();
  const Row r = has_csysid ? b.row({"gid", "csysid"}) : b.row({"gid"});
  GeometryEntry g;
  g.id = d.other_id(r, 0);
  d.claim_id("geometry", g.id, r.where(0));
  if (has_csysid) r.global_coordinates_only(1);
  g.where = r.where();
  return g;
}

double uniform_scale(const DeckReader& d, const SourceLocation& where) {
  const auto s = d.frame().transform.uniform_scale();
  if (!s)
    throw InputError(
        where,
        "this geometry inside an *INCLUDE with unequal scale factors is not supported yet by abut");
  return *s;
}

void require_axis_aligned(const DeckReader& d, const SourceLocation& where) {
  if (!d.frame().transform.axis_aligned()) {
    throw InputError(
        where,
        "this geometry inside an *INCLUDE that rotates its axes is not supported yet by abut");
  }
}

}  // namespace

void read_geometry_box(DeckReader& d, Block& b) {
  GeometryEntry g = head(d, b, true);
  const Row r = b.row({"x1", "y1", "z1", "x2", "y2", "z2"});
  require_axis_aligned(d, b.where());
  const Vec3 p1 = d.frame().transform.point(point(r, 0));
  const Vec3 p2 = d.frame().transform.point(point(r, 3));
  GeometryBox box;
  for (int k = 0; k < 3; ++k) {
    box.corner1[k] = std::min(p1[k], p2[k]);
    box.corner2[k] = std::max(p1[k], p2[k]);
  }
  g.geometry = box;
  d.model.geometries.push_back(g);
}

void read_geometry_sphere(DeckReader& d, Block& b) {
  GeometryEntry g = head(d, b, true);
  const Row r = b.row({"x", "y", "z", "R1", "R2"});
  GeometrySphere sphere;
  sphere.radius1 = r.number(3);
  r.require(sphere.radius1 > 0.0, 3, "expected a radius > 0");
  sphere.radius2 = r.number_or(4, 0.0);
  r.require(sphere.radius2 == 0.0 || sphere.radius2 > sphere.radius1, 4,
            "expected 0 (a ball of radius R1) or an outer radius > R1 (a shell)");
  const double s = uniform_scale(d, b.where());
  sphere.centre = d.frame().transform.point(point(r, 0));
  sphere.radius1 *= s;
  sphere.radius2 *= s;
  g.geometry = sphere;
  d.model.geometries.push_back(g);
}

void read_geometry_pipe(DeckReader& d, Block& b) {
  GeometryEntry g = head(d, b, true);
  const Row r = b.row({"x1", "y1", "z1", "x2", "y2", "z2", "R1", "R2"});
  GeometryPipe pipe;
  const Vec3 e1 = point(r, 0);
  const Vec3 e2 = point(r, 3);
  r.require(norm(e2 - e1) > 0.0, 3, "expected the second end centre to differ from the first");
  pipe.radius1 = r.number(6);
  r.require(pipe.radius1 >= 0.0, 6, "expected a radius >= 0");
  pipe.radius2 = r.number_or(7, 0.0);
  r.require(pipe.radius2 >= 0.0, 7, "expected a radius >= 0");
  r.require(pipe.radius1 > 0.0 || pipe.radius2 > 0.0, 7, "expected at least one radius > 0");
  pipe.radius3 = pipe.radius1;
  pipe.radius4 = pipe.radius2;
  if (auto r2 = b.optional_row({"R3", "R4", "v_x", "v_y", "v_z", "alpha"})) {
    pipe.radius3 = r2->number_or(0, pipe.radius1);
    r2->require(pipe.radius3 >= 0.0, 0, "expected a radius >= 0");
    pipe.radius4 = r2->number_or(1, pipe.radius2);
    r2->require(pipe.radius4 >= 0.0, 1, "expected a radius >= 0");
    pipe.reference = {r2->number_or(2, 0.0), r2->number_or(3, 0.0), r2->number_or(4, 0.0)};
    pipe.sector_angle = r2->number_or(5, 360.0);
    r2->require(pipe.sector_angle > 0.0 && pipe.sector_angle <= 360.0, 5,
                "expected a sector angle in (0, 360] degrees");
    if (pipe.sector_angle < 360.0) {
      r2->require(norm(pipe.reference) > 0.0, 2,
                  "a sector (alpha < 360) needs a non-zero reference vector v");
    }
  }
  const double s = uniform_scale(d, b.where());
  pipe.end1 = d.frame().transform.point(e1);
  pipe.end2 = d.frame().transform.point(e2);
  pipe.radius1 *= s;
  pipe.radius2 *= s;
  pipe.radius3 *= s;
  pipe.radius4 *= s;
  pipe.reference = normalized(d.frame().transform.linear(pipe.reference));
  g.geometry = pipe;
  d.model.geometries.push_back(g);
}

void read_geometry_ellipsoid(DeckReader& d, Block& b) {
  GeometryEntry g = head(d, b, true);
  const Row r = b.row({"x", "y", "z", "Rx", "Ry", "Rz"});
  require_axis_aligned(d, b.where());
  GeometryEllipsoid e;
  e.centre = d.frame().transform.point(point(r, 0));
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(3 + k);
    e.semi_axes[k] = r.number(i);
    r.require(e.semi_axes[k] > 0.0, i, "expected a semi-axis > 0");
    e.semi_axes[k] *= std::fabs(d.frame().transform.diagonal(k));
  }
  g.geometry = e;
  d.model.geometries.push_back(g);
}

void read_geometry_part(DeckReader& d, Block& b) {
  GeometryEntry g = head(d, b, false);
  const Row r = b.row({"pid"});
  GeometryPart part;
  part.part_id = d.part_id(r, 0);
  d.geometry_parts.emplace_back(part.part_id, r.where(0));
  g.geometry = part;
  d.model.geometries.push_back(g);
}

}  // namespace abut::deck
