// The contact settings in the library's words (describe.hpp). The contact library has no fmt:
// numbers go through snprintf.
#include "abut/contact/describe.hpp"

#include <cmath>
#include <cstdio>
#include <type_traits>
#include <variant>

namespace abut {

namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

// " x f(t)" after a coefficient that a function of time multiplies.
std::string in_time(const TimeFactor& f) { return f ? " x f(t)" : ""; }

std::string describe_normal(const ContactSettings& s) {
  std::string text = std::visit(
      [](const auto& law) -> std::string {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<Law, LinearPenalty>)
          return "linear penalty";
        else if constexpr (std::is_same_v<Law, CurvePenalty>)
          return "penalty curve p(d)";
        else
          return "exponential overclosure, c0 = " + number(law.c0) + ", p0 = " + number(law.p0);
      },
      s.normal_law);
  text += in_time(s.normal_in_time);
  text += s.sense == ContactSense::Positive   ? ", positive side"
          : s.sense == ContactSense::Negative ? ", negative side"
                                              : ", bilateral";
  if (s.clearance) text += ", clearance = " + number(*s.clearance);
  if (s.adhesion) text += ", adhesion up to " + number(s.adhesion->max_stress);
  return text;
}

std::string describe_stiffness(const StiffnessSettings& k) {
  std::string text;
  switch (k.rule) {
    case StiffnessRule::FacetPenalty:
      return "facet penalty";
    case StiffnessRule::Main:
      text = "main side";
      break;
    case StiffnessRule::Mean:
      text = "mean of both sides";
      break;
    case StiffnessRule::Maximum:
      text = "maximum of both sides";
      break;
    case StiffnessRule::Minimum:
      text = "minimum of both sides";
      break;
    case StiffnessRule::Series:
      text = "both sides in series";
      break;
  }
  text += ", scale = " + number(k.scale);
  if (k.minimum > 0.0) text += ", minimum = " + number(k.minimum);
  if (std::isfinite(k.maximum)) text += ", maximum = " + number(k.maximum);
  return text;
}

std::string describe_gaps(const GapSettings& g) {
  std::string text = "shell gaps x " + number(g.scale);
  if (g.mesh_fraction) text += ", at most " + number(*g.mesh_fraction) + " of the mesh size";
  if (std::isfinite(g.max_secondary)) text += ", max_secondary = " + number(g.max_secondary);
  if (std::isfinite(g.max_main)) text += ", max_main = " + number(g.max_main);
  if (g.skip_close) text += ", facets initially within the gap skipped";
  if (g.zero_at_free_edges) text += ", zero at free edges";
  if (g.padding > 0.0) text += ", padding = " + number(g.padding);
  if (g.border == GapSettings::Border::Square) text += ", square border";
  if (g.border == GapSettings::Border::Round) text += ", round border";
  return text;
}

std::string describe_edges(const EdgeSettings& e) {
  switch (e.selection) {
    case EdgeSelection::None:
      return "none";
    case EdgeSelection::ShellBorders:
      return "shell borders";
    case EdgeSelection::SharpSolidEdges:
      return "sharp solid edges and shell borders (edge angle " + number(e.angle) + ")";
    case EdgeSelection::SharpSolidAllShells:
      return "sharp solid edges and all shell edges (edge angle " + number(e.angle) + ")";
    case EdgeSelection::AllEdges:
      return "all edges";
  }
  return "none";
}

std::string describe_filter(const FrictionFilter& f) {
  switch (f.kind) {
    case FrictionFilter::Kind::None:
      return "";
    case FrictionFilter::Kind::Simple:
      return ", filtered with weight " + number(f.xfreq);
    case FrictionFilter::Kind::Period:
      return ", filtered over a period of " + number(f.xfreq);
    case FrictionFilter::Kind::Frequency:
      return ", filtered above " + number(f.xfreq) + " Hz";
  }
  return "";
}

}  // namespace

std::string describe(const TangentialLaw& law) {
  return std::visit(
      [](const auto& l) -> std::string {
        using Law = std::decay_t<decltype(l)>;
        if constexpr (std::is_same_v<Law, Frictionless>) {
          return "frictionless";
        } else if constexpr (std::is_same_v<Law, Sticking>) {
          return "sticking";
        } else if constexpr (std::is_same_v<Law, Tresca>) {
          return "Tresca, factor_static = " + number(l.factor_static) + in_time(l.static_in_time) +
                 ", factor_dynamic = " + number(l.factor_dynamic) + in_time(l.dynamic_in_time) +
                 ", shear_yield = " + number(l.shear_yield) + in_time(l.yield_in_time);
        } else {
          if (l.function) return "Coulomb, mu = function of the contact state";
          return std::visit(
              [&l](const auto& m) -> std::string {
                using Model = std::decay_t<decltype(m)>;
                if constexpr (std::is_same_v<Model, ViscousFriction>)
                  return "Coulomb, mu(p, V) viscous law, fric = " + number(m.fric);
                else if constexpr (std::is_same_v<Model, DarmstadFriction>)
                  return "Coulomb, mu(p, V) Darmstad law, fric = " + number(m.fric);
                else if constexpr (std::is_same_v<Model, RenardFriction>)
                  return "Coulomb, mu(V) Renard law, mu_static = " + number(m.c[0]) +
                         ", mu_dynamic = " + number(m.c[1]);
                else
                  return "Coulomb, mu_static = " + number(l.mu_static) + in_time(l.static_in_time) +
                         ", mu_dynamic = " + number(l.mu_dynamic) + in_time(l.dynamic_in_time);
              },
              l.model);
        }
      },
      law);
}

ContactDescription describe(const ContactSettings& s) {
  ContactDescription d;
  const bool s2s = s.discretisation == Discretisation::SurfaceToSurface;
  d.discretisation =
      s2s ? "surface-to-surface (accuracy level " + std::to_string(s.accuracy_level) + ")"
          : "node-to-surface";
  d.discretisation += s.one_way ? ", one-way" : ", symmetric";
  if (!s.removed_nodes.empty())
    d.discretisation +=
        ", " + std::to_string(s.removed_nodes.nodes().size()) + " tied nodes removed";
  d.normal_law = describe_normal(s);

  d.tangential_law = s.freeze ? "frozen: tied in every direction from the start"
                              : describe(s.tangential_law) + describe_filter(s.friction_filter);
  if (s.stick_stress) d.tangential_law += ", sticking until " + number(*s.stick_stress);
  if (s.tangential_penalty_factor.of_penetration) d.tangential_law += ", tangential penalty x g(d)";
  if (s.tangential_penalty_factor.in_time) d.tangential_law += ", tangential penalty x f(t)";
  if (!s.pair_frictions.empty())
    d.tangential_law += ", " + std::to_string(s.pair_frictions.size()) + " part-pair laws";

  d.stiffness_rule = describe_stiffness(s.stiffness);
  if (!s.pair_scales.empty())
    d.stiffness_rule += ", " + std::to_string(s.pair_scales.size()) + " part-pair scales";
  d.gap_rule = describe_gaps(s.gaps);
  d.edge_rule = describe_edges(s.edges);
  d.erosion_rule =
      std::string(s.erosion.remove_facets ? "eroded facets removed" : "eroded facets kept") +
      (s.erosion.keep_free_nodes ? ", free nodes kept" : ", free nodes removed");
  return d;
}

}  // namespace abut
