// The checks of a contact interface's settings and surfaces, in the library's own terms.
#include <cmath>
#include <string>

#include "interface_impl.hpp"

namespace abut {

namespace {

// A tangential law and its filter that the steps can work with; `law_setting` and
// `filter_setting` name them in the error.
void check_friction(const TangentialLaw& law, const FrictionFilter& filter, const char* law_setting,
                    const char* filter_setting) {
  auto fail = [](const char* setting, const std::string& message) {
    throw ContactSetupError(setting, message);
  };
  if (const auto* c = std::get_if<Coulomb>(&law)) {
    if (!(c->mu_static >= 0.0) || !(c->mu_dynamic >= 0.0))
      fail(law_setting, "the friction coefficients must be >= 0");
    if (!c->function && std::holds_alternative<std::monostate>(c->model) &&
        c->mu_dynamic > c->mu_static)
      fail(law_setting, "the dynamic friction coefficient must not exceed the static one");
  }
  if (const auto* t = std::get_if<Tresca>(&law)) {
    if (!(t->shear_yield > 0.0))
      fail(law_setting, "Tresca friction needs a shear yield stress > 0");
    if (!(t->factor_static >= 0.0 && t->factor_dynamic >= 0.0 &&
          t->factor_dynamic <= t->factor_static))
      fail(law_setting, "Tresca friction needs shear factors with 0 <= dynamic <= static");
  }
  if (filter.kind != FrictionFilter::Kind::None && !(filter.xfreq > 0.0))
    fail(filter_setting, "the filter coefficient must be > 0");
  if (filter.kind == FrictionFilter::Kind::Simple && !(filter.xfreq <= 1.0))
    fail(filter_setting, "the simple filter coefficient must be in (0, 1]");
}

}  // namespace

void InterfaceImpl::validate(const ContactSurface& s1, const ContactSurface& s2,
                             std::size_t coordinates) const {
  const ContactSettings& s = settings_;
  auto fail = [](const char* setting, const std::string& message) {
    throw ContactSetupError(setting, message);
  };
  if (s.accuracy_level < 1) fail("accuracy_level", "expected 1 (low), 2 (standard) or more (high)");
  if (!s1.parent.empty() || !s2.parent.empty())
    fail("surface",
         "facets of curved faces (ContactSurface::parent) are taken by the static "
         "contact only yet");
  if (!(s.damping >= 0.0)) fail("damping", "the fraction of critical damping must be >= 0");
  if (!(s.end_time >= s.begin_time)) fail("end_time", "the contact must not end before it begins");
  if (!(s.initial_offset >= 0.0))
    fail("initial_offset", "the initial penetration offset must be >= 0");
  if (s.initial_max && !(*s.initial_max >= 0.0)) fail("initial_max", "must be >= 0");
  if (!(s.edge_tolerance >= 0.0)) fail("edge_tolerance", "the edge tolerance must be >= 0");
  if (!(s.edge_angle > 0.0 && s.edge_angle <= 180.0))
    fail("edge_angle", "expected an angle in (0, 180] degrees");
  if (s.stick_stress && !(*s.stick_stress > 0.0))
    fail("stick_stress", "the sticking failure stress must be > 0");
  if (s.search_margin && !(*s.search_margin > 0.0))
    fail("search_margin", "the search margin must be > 0");
  if (s.detection_depth && !(*s.detection_depth > 0.0))
    fail("detection_depth", "the detection depth must be > 0");
  if (s.tangential_penalty && !(*s.tangential_penalty > 0.0))
    fail("tangential_penalty", "the tangential penalty must be > 0");
  if (s.clearance && !std::isfinite(*s.clearance))
    fail("clearance", "the clearance must be a finite length");
  if (s.adhesion && !(s.adhesion->gap > 0.0 && s.adhesion->max_stress >= 0.0 &&
                      s.adhesion->fluid_viscosity >= 0.0))
    fail("adhesion",
         "adhesion needs a gap > 0, a maximum adhesive stress >= 0 and a viscosity >= 0");
  if (s.freeze && s.stick_stress)
    fail("freeze", "a frozen contact cannot also have a sticking failure stress");
  check_friction(s.tangential_law, s.friction_filter, "tangential_law", "friction_filter");
  for (const PairFriction& pf : s.pair_frictions)
    check_friction(pf.law, pf.filter, "pair_frictions", "pair_frictions");
  if (const auto* c = std::get_if<CurvePenalty>(&s.normal_law); c && !c->pressure)
    fail("normal_law", "the penalty curve is missing");
  const StiffnessSettings& k = s.stiffness;
  if (!(k.scale > 0.0) || !(k.minimum >= 0.0) || !(k.maximum > k.minimum))
    fail("stiffness", "expected a stiffness scale > 0 and 0 <= minimum < maximum");
  for (const PairScale& ps : s.pair_scales)
    if (!(ps.scale > 0.0) || !std::isfinite(ps.scale))
      fail("pair_scales", "a penalty scale factor must be > 0");
  const GapSettings& g = s.gaps;
  if (!(g.scale >= 0.0) || !std::isfinite(g.scale)) fail("gaps", "the gap scale must be >= 0");
  if (!(g.max_secondary >= 0.0) || !(g.max_main >= 0.0))
    fail("gaps", "the maximum gaps must be >= 0");
  if (g.mesh_fraction && !(*g.mesh_fraction > 0.0))
    fail("gaps", "the fraction of the mesh size must be > 0");
  if (!(g.padding >= 0.0) || !std::isfinite(g.padding))
    fail("gaps", "the padding must be >= 0 and finite");
  if (g.padding > 0.0 && g.mesh_fraction)
    fail("gaps", "a padding cannot be combined with the mesh-size cap, which would cap it");
  if (s1.size() == 0) fail("surface1", "surface 1 has no facets");
  if (s2.size() == 0) fail("surface2", "surface 2 has no facets");
  const bool radioss = k.rule != StiffnessRule::FacetPenalty;
  int which = 1;
  for (const ContactSurface* surface : {&s1, &s2}) {
    const std::string name = "surface" + std::to_string(which++);
    const std::size_t n = surface->size();
    if (surface->part.size() != n || surface->penalty.size() != n ||
        surface->thickness.size() != n || surface->twin.size() != n ||
        surface->young_modulus.size() != n)
      fail(name.c_str(),
           "part, penalty, thickness, twin and Young's modulus need one entry per facet");
    for (std::size_t f = 0; f < n; ++f) {
      if (!(surface->penalty[f] > 0.0) || !std::isfinite(surface->penalty[f]))
        fail(name.c_str(),
             "the penalty stiffness of part " + std::to_string(surface->part[f]) + " must be > 0");
      if (!(surface->thickness[f] > 0.0))
        fail(name.c_str(),
             "a facet of part " + std::to_string(surface->part[f]) + " has no positive thickness");
      const std::int32_t twin = surface->twin[f];
      const bool shell = twin >= 0;
      if (shell && (static_cast<std::size_t>(twin) >= n || twin == static_cast<std::int32_t>(f) ||
                    surface->twin[twin] != static_cast<std::int32_t>(f)))
        fail(name.c_str(), "the two sides of a shell must name each other as twins");
      if (shell && s.sense == ContactSense::Negative)
        fail("sense",
             "contact from behind (sense NEGATIVE) has no meaning on shells: both of their sides "
             "are contact surfaces");
      if (radioss && shell && !(surface->young_modulus[f] > 0.0))
        fail("stiffness", "the Radioss stiffness rules need each shell's Young's modulus (part " +
                              std::to_string(surface->part[f]) + ")");
      if (radioss && !shell &&
          (surface->bulk_modulus.size() != n || surface->element_volume.size() != n ||
           !(surface->bulk_modulus[f] > 0.0) || !(surface->element_volume[f] > 0.0)))
        fail(
            "stiffness",
            "the Radioss stiffness rules need each facet's bulk modulus and element volume (part " +
                std::to_string(surface->part[f]) + ")");
      for (auto node : surface->facets[f])
        if (node < 0 || static_cast<std::size_t>(node) >= mass_.size() ||
            static_cast<std::size_t>(node) >= coordinates)
          fail(name.c_str(),
               "a facet refers to node index " + std::to_string(node) + " beyond the nodal arrays");
    }
  }
}

}  // namespace abut
