// *CONTACT_TOOL (abut's own): an analytic rigid tool, a plane, cylinder or sphere given by
// parameters and a motion, that a *CONTACT names as its surface 2 (entype_2 TOOL, enid_2 tid).
// After Metafor's rigid contact matrices of analytic lines and arcs (seed 002). Keyword reference:
// docs/deck-reference.md.
#include <cmath>

#include "deck_reader.hpp"

namespace abut::deck {

void read_contact_tool(DeckReader& d, Block& b) {
  RigidTool t;
  const Row r1 = b.row({"tid", "shape", "side"});
  t.id = d.other_id(r1, 0);
  d.claim_id("tool", t.id, r1.where(0));
  t.where = r1.where();
  if (!r1.given(1)) r1.fail(1, "expected a tool shape: PLANE, CYLINDER or SPHERE");
  t.tool.shape = word_choice(r1, 1, ToolShape::Plane,
                             {{"PLANE", ToolShape::Plane},
                              {"CYLINDER", ToolShape::Cylinder},
                              {"SPHERE", ToolShape::Sphere}},
                             "PLANE, CYLINDER or SPHERE");
  t.tool.side = word_choice(r1, 2, ToolSide::Outside,
                            {{"OUTSIDE", ToolSide::Outside}, {"INSIDE", ToolSide::Inside}},
                            "OUTSIDE (the body lies outside the tool) or INSIDE (in a pipe, a cup, "
                            "or the plane's other side)");

  const Row r2 =
      b.row({"x0", "y0", "z0", "nx", "ny", "nz", "radius", "length", "dx", "dy", "dz", "span"});
  const Vec3 point{r2.number(0), r2.number(1), r2.number(2)};
  t.tool.point = d.frame().transform.point(point);
  const bool sphere = t.tool.shape == ToolShape::Sphere;
  if (sphere) {
    for (std::size_t k = 3; k < 6; ++k)
      if (r2.given(k)) r2.fail(k, "a sphere has no direction: leave nx, ny, nz empty");
  } else {
    const Vec3 n{r2.number(3), r2.number(4), r2.number(5)};
    const double length = norm(n);
    r2.require(length > 0.0, 3,
               t.tool.shape == ToolShape::Plane ? "expected a nonzero normal (nx, ny, nz)"
                                                : "expected a nonzero axis direction (nx, ny, nz)");
    d.require_unrotated(r2.where(3), "a tool's direction");
    t.tool.axis = n / length;
  }
  if (t.tool.shape == ToolShape::Plane) {
    if (r2.given(6)) r2.fail(6, "a plane has no radius: leave it empty");
  } else {
    t.tool.radius = r2.number(6);
    r2.require(t.tool.radius > 0.0, 6, "expected a radius > 0");
    d.require_unrotated(r2.where(6), "a tool's radius");
  }
  if (t.tool.shape == ToolShape::Cylinder) {
    if (r2.given(7)) {
      t.tool.length = r2.number(7);
      r2.require(t.tool.length > 0.0, 7, "expected a length > 0 (empty: infinite)");
    }
  } else if (r2.given(7)) {
    r2.fail(7, "only a cylinder has a length: leave it empty");
  }
  // Ends across the extrusion (Metafor's matrix segments): a strip of a plane from the point along
  // (dx, dy, dz) for span [length], or an arc of a cylinder from the radial direction (dx, dy, dz)
  // for span [degrees] about its axis.
  if (r2.given(8) || r2.given(9) || r2.given(10) || r2.given(11)) {
    if (sphere) r2.fail(8, "a sphere has no ends: leave dx, dy, dz and span empty");
    const Vec3 start{r2.number(8), r2.number(9), r2.number(10)};
    const Vec3 across = start - t.tool.axis * dot(start, t.tool.axis);
    r2.require(norm(across) > 1e-9 * norm(start) && norm(start) > 0.0, 8,
               t.tool.shape == ToolShape::Plane
                   ? "expected a direction in the plane, along which the strip ends (dx, dy, dz)"
                   : "expected a radial direction, where the arc starts (dx, dy, dz; not along "
                     "the axis)");
    d.require_unrotated(r2.where(8), "a tool's ends");
    t.tool.start = across / norm(across);
    const double span = r2.number(11);
    if (t.tool.shape == ToolShape::Plane) {
      r2.require(span > 0.0, 11, "expected the strip's width > 0 [length]");
      t.tool.span = span;
    } else {
      r2.require(span > 0.0 && span <= 360.0, 11, "expected the arc's angle in (0, 360] degrees");
      t.tool.span = span * 3.14159265358979323846 / 180.0;
    }
  }

  const std::size_t index = d.model.tools.size();
  if (auto r3 = b.optional_row(
          {"fid_vx", "sf_vx", "fid_vy", "sf_vy", "fid_vz", "sf_vz", "fid_spin", "sf_spin"})) {
    if (r3->given(0) || r3->given(2) || r3->given(4))
      d.require_unrotated(r3->where(), "a tool's velocity");
    for (std::size_t k = 0; k < 3; ++k) {
      t.velocity_scale[k] = r3->number_or(2 * k + 1, 1.0);
      if (const auto fid = d.optional_other_id(*r3, 2 * k))
        d.bind_function(*fid, r3->where(2 * k),
                        [index, k](Model& m, FunctionRef f) { m.tools[index].velocity[k] = f; });
      else if (r3->given(2 * k + 1))
        r3->fail(2 * k + 1, "a scale factor without its curve (fid) would do nothing");
    }
    t.spin_scale = r3->number_or(7, 1.0);
    if (const auto fid = d.optional_other_id(*r3, 6)) {
      if (t.tool.shape != ToolShape::Cylinder)
        r3->fail(6, "only a cylinder spins about its axis (a roller): not supported yet for " +
                        std::string(sphere ? "a sphere" : "a plane"));
      if (std::isfinite(t.tool.span))
        r3->fail(6, "an arc does not spin (its ends would turn with it): give the whole cylinder");
      d.bind_function(*fid, r3->where(6),
                      [index](Model& m, FunctionRef f) { m.tools[index].spin = f; });
    } else if (r3->given(7)) {
      r3->fail(7, "a scale factor without its curve (fid_spin) would do nothing");
    }
  }
  d.model.tools.push_back(t);
}

}  // namespace abut::deck

namespace abut::deck {

void check_tool_contact(const Model& model, const ContactSpec& c) {
  if (c.surface2.type != EntityType::Tool) return;
  model.tool(c.surface2);  // the tool exists
  const auto at = [&model, &c](std::string_view setting) { return model.place_of(c, setting); };
  const auto given = [&model, &c](std::string_view setting) { return model.gives(c, setting); };
  const std::string tool = " with an analytic tool (surface 2 TOOL) is not supported yet";
  if (c.symmetric.value_or(false))
    throw InputError(at("symmetric"), "symmetric contact" + tool +
                                          ": the tool has no points of its own (one-way "
                                          "node to surface)");
  if (given("discretisation") && c.discretisation != Discretisation::NodeToSurface)
    throw InputError(
        at("discretisation"),
        "surface-to-surface contact" + tool + ": the nodes of surface 1 touch the tool (give N2S)");
  if (c.adjust_depth) throw InputError(at("adjust"), "ADJUST" + tool);
  if (given("erosion")) throw InputError(at("erosion"), "*CONTACT_EROSION" + tool);
  if (c.element_penalty)
    throw InputError(at("stiffness"),
                     "the ELEMENT penalty rule" + tool + " (give pfac or the automatic rule)");
  if (c.exchanges_heat())
    throw InputError(at(c.conductance       ? "conductance"
                        : c.thermal.valid() ? "thermal"
                                            : "friction_heat"),
                     "heat exchange" + tool);
  if (c.wear1.valid() || c.wear2.valid()) throw InputError(at("wear"), "wear" + tool);
  if (c.gaps.border != GapSettings::Border::Cut)
    throw InputError(with_field(at("gaps"), "ishape"),
                     "ishape" + tool + " (the tool has no shell border)");
}

}  // namespace abut::deck
