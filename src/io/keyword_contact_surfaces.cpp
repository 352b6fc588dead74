// The keywords about what a contact surface is made of: *CONTACT_GAP (shell gaps, Radioss
// /INTER/TYPE25 Igap, Gap_scale, %mesh_size, Gap_max_s, Gap_max_m, Igap0), *CONTACT_EDGE (Iedge,
// Edge_angle) and *CONTACT_EROSION (Radioss Idel, Abaqus nodal erosion). Seeds 001 and 004
// (../shared/seeds/); the formulas in include/abut/contact/gap.hpp and settings.hpp.
#include <limits>

#include "deck_reader.hpp"

namespace abut::deck {

void read_contact_gap(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "igap", "gap_scale", "pct_mesh", "gap_max_s", "gap_max_m", "igap0",
                       "gpad", "shell_side", "ishape"});
  const int igap = word_choice(r, 1, 1, {{"1", 1}, {"2", 2}, {"3", 3}},
                               "1 (variable gap), 2 (variable, close pairs of self contact "
                               "skipped) or 3 (variable, capped by the mesh size)");
  GapSettings g;
  g.scale = r.number_or(2, 1.0);
  r.require(g.scale >= 0.0, 2, "expected a gap scale factor >= 0");
  g.skip_close = igap == 2;
  if (igap == 3) {
    g.mesh_fraction = r.number_or(3, 0.4);
    r.require(*g.mesh_fraction > 0.0, 3, "expected a fraction of the mesh size > 0");
  } else if (r.given(3)) {
    r.fail(3, "pct_mesh caps the gap with igap = 3 only: leave it empty or set igap to 3");
  }
  const double unbounded = std::numeric_limits<double>::infinity();
  g.max_secondary = r.number_or(4, unbounded);
  r.require(g.max_secondary > 0.0, 4, "expected a maximum secondary gap > 0");
  g.max_main = r.number_or(5, unbounded);
  r.require(g.max_main > 0.0, 5, "expected a maximum main gap > 0");
  g.zero_at_free_edges =
      word_choice(r, 6, false, {{"0", false}, {"1000", false}, {"1", true}},
                  "0 or 1000 (gap kept at free shell edges) or 1 (zero gap for nodes on them)");
  g.padding = r.number_or(7, 0.0);
  r.require(g.padding >= 0.0, 7, "expected a padding >= 0 [length]");
  if (g.padding > 0.0 && igap == 3)
    r.fail(7, "gpad cannot be combined with igap 3, whose mesh-size cap would cap the padding");
  using Border = GapSettings::Border;
  g.border = word_choice(r, 9, Border::Cut,
                         {{"CUT", Border::Cut},
                          {"SQUARE", Border::Square},
                          {"1", Border::Square},
                          {"ROUND", Border::Round},
                          {"2", Border::Round}},
                         "CUT (the surface ends at a shell's free border), SQUARE (Radioss "
                         "Ishape 1) or ROUND (Ishape 2)");
  using Sides = ContactSpec::ShellSides;
  const Sides sides = word_choice(r, 8, Sides::Both,
                                  {{"BOTH", Sides::Both},
                                   {"OPENGAP", Sides::Both},
                                   {"NORM", Sides::Normal},
                                   {"REVNORM", Sides::Reverse},
                                   {"OVERLAP", Sides::Overlap}},
                                  "BOTH (or OPENGAP), NORM, REVNORM or OVERLAP (OptiStruct "
                                  "MORIENT)");
  contact_place(d, r, "gaps", 1);
  contact_place(d, r, "shell_sides", 8);
  refine_contact(d, r, [g, sides](ContactSpec& c) {
    c.gaps = g;
    c.main_shell_sides = sides;
  });
}

void read_contact_edge(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "iedge", "edge_angle"});
  EdgeSettings e;
  e.selection = word_choice(r, 1, EdgeSelection::None,
                            {{"NONE", EdgeSelection::None},
                             {"1000", EdgeSelection::None},
                             {"BORDERS", EdgeSelection::ShellBorders},
                             {"1", EdgeSelection::ShellBorders},
                             {"SHARP", EdgeSelection::SharpSolidEdges},
                             {"11", EdgeSelection::SharpSolidEdges},
                             {"SHARP_ALL_SHELLS", EdgeSelection::SharpSolidAllShells},
                             {"13", EdgeSelection::SharpSolidAllShells},
                             {"ALL", EdgeSelection::AllEdges},
                             {"22", EdgeSelection::AllEdges}},
                            "NONE (1000), BORDERS (1), SHARP (11), SHARP_ALL_SHELLS (13) or "
                            "ALL (22)");
  const bool sharp = e.selection == EdgeSelection::SharpSolidEdges ||
                     e.selection == EdgeSelection::SharpSolidAllShells;
  if (r.given(2) && !sharp)
    r.fail(2, "edge_angle selects sharp solid edges for iedge SHARP and SHARP_ALL_SHELLS only");
  e.angle = r.number_or(2, 135.0);
  r.require(e.angle > 0.0 && e.angle <= 180.0, 2, "expected an angle in (0, 180] degrees");
  contact_place(d, r, "edges", 1);
  refine_contact(d, r, [e](ContactSpec& c) { c.edges = e; });
}

void read_contact_erosion(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "facets", "free_nodes"});
  ErosionSettings e;
  e.remove_facets = word_choice(
      r, 1, true, {{"REMOVE", true}, {"1", true}, {"2", true}, {"KEEP", false}, {"1000", false}},
      "REMOVE (Radioss Idel 1, 2) or KEEP (Idel 1000)");
  // Radioss Idel 1 and 2 also take free nodes off the secondary side.
  const bool idel = r.given(1) && (r.text(1) == "1" || r.text(1) == "2");
  e.keep_free_nodes = word_choice(r, 2, !idel, {{"KEEP", true}, {"REMOVE", false}},
                                  "KEEP (free nodes stay as point masses) or REMOVE (Abaqus "
                                  "nodal erosion)");
  contact_place(d, r, "erosion", 1);
  refine_contact(d, r, [e](ContactSpec& c) { c.erosion = e; });
}

}  // namespace abut::deck
