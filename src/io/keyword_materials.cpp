// *MAT_ELASTIC, *MAT_MOONEY_RIVLIN, *MAT_RIGID, *MAT_METAL, *MAT_JC, *PART, *PART_SHELL.
#include <optional>

#include "deck_reader.hpp"

namespace abut::deck {
namespace {

// `thpid`: the field of the thermal property id on r, if the material has one.
void add_material(DeckReader& d, const Row& r, MaterialParams params,
                  std::optional<std::size_t> thpid = std::nullopt) {
  const std::int64_t id = d.material_id(r, 0);
  d.claim_id("material", id, r.where(0));
  const std::int64_t thermal_id = thpid ? thermal_property_id(d, r, *thpid) : 0;
  d.model.materials.push_back({id, params, r.where(), thermal_id});
}

double density(const Row& r, std::size_t i) {
  const double rho = r.number(i);
  r.require(rho > 0.0, i, "expected a density > 0");
  return rho;
}

void unused_field(const Row& r, std::size_t i) {
  r.require(!r.given(i) || parse_number(r.text(i)) == 0.0, i,
            "this field is unused: leave it empty");
}

// mid, rho, E, nu, did of *MAT_ELASTIC, *MAT_METAL and *MAT_JC (the metals read did
// themselves; thpid, field 5, is read by add_material).
template <class Params>
Params isotropic_elasticity(const Row& r, bool damage = false) {
  Params p;
  p.density = density(r, 1);
  p.young = r.number(2);
  r.require(p.young > 0.0, 2, "expected a Young's modulus > 0");
  p.poisson = r.number_or(3, 0.0);
  r.require(p.poisson >= 0.0 && p.poisson < 0.5, 3, "poisson must be in [0, 0.5)");
  if (!damage) r.unsupported_unless(4, 0.0, "a damage property (did) on this material");
  return p;
}

}  // namespace

void read_mat_elastic(DeckReader& d, Block& b) {
  const Row r = b.row({"mid", "rho", "E", "nu", "did", "thpid"});
  const ElasticParams p = isotropic_elasticity<ElasticParams>(r);
  if (auto r2 = b.optional_row({"a", "b", "c", "c_dec"})) {
    r2->unsupported_unless(0, 0.0, "non-linear elasticity (a)");
    r2->unsupported_unless(1, 0.0, "non-linear elasticity (b)");
    r2->unsupported_unless(2, 0.0, "material damping (c)");
    r2->unsupported_unless(3, 0.0, "material damping (c_dec)");
  }
  add_material(d, r, p, 5);
}

void read_mat_mooney_rivlin(DeckReader& d, Block& b) {
  const Row r1 = b.row({"mid", "rho", "K", "-", "-", "tid"});
  const Row r2 = b.row({"C1", "C2", "alpha1", "beta1", "alpha2", "beta2", "alpha3", "beta3"});
  MooneyRivlinParams p;
  p.density = density(r1, 1);
  p.bulk = r1.number(2);
  r1.require(p.bulk > 0.0, 2, "expected a bulk modulus K > 0");
  unused_field(r1, 3);
  unused_field(r1, 4);
  p.c1 = r2.number(0);
  p.c2 = r2.number_or(1, 0.0);
  r2.require(p.c1 + p.c2 > 0.0, 1,
             "expected C1 + C2 > 0 (the initial shear modulus is 2 (C1 + C2))");
  for (std::size_t k = 0; k < 3; ++k) {
    p.alpha[k] = r2.number_or(2 + 2 * k, 0.0);
    r2.require(p.alpha[k] >= 0.0, 2 + 2 * k, "expected a viscous stiffness alpha >= 0");
    p.beta[k] = r2.number_or(3 + 2 * k, 0.0);
    r2.require(p.beta[k] >= 0.0, 3 + 2 * k, "expected a relaxation time beta >= 0");
  }
  if (auto r3 = b.optional_row({"alpha4", "beta4"})) {
    p.alpha[3] = r3->number_or(0, 0.0);
    r3->require(p.alpha[3] >= 0.0, 0, "expected a viscous stiffness alpha >= 0");
    p.beta[3] = r3->number_or(1, 0.0);
    r3->require(p.beta[3] >= 0.0, 1, "expected a relaxation time beta >= 0");
  }
  add_material(d, r1, p, 5);
}

void read_mat_rigid(DeckReader& d, Block& b) {
  const Row r = b.row({"mid", "rho", "-", "-", "-", "thpid"});
  RigidParams p;
  p.density = density(r, 1);
  for (std::size_t i : {2, 3, 4}) unused_field(r, i);
  add_material(d, r, p, 5);  // a rigid body conducts heat (a hot tool) but does not expand
}

void read_part(DeckReader& d, Block& b) {
  if (b.done()) throw InputError(b.where(), "missing data line: expected pid, mid");
  while (!b.done()) {
    Part part;
    if (auto title = b.title()) {
      part.title = *title;
      if (b.done() || b.next_is_title()) {
        throw InputError(b.where(), "the part title \"" + part.title +
                                        "\" must be followed by its pid, mid line");
      }
    }
    const Row r =
        b.row({"pid", "mid", "-", "h", "alpha_max", "dt_erode", "eps_geo_erode", "eps_v_erode"});
    part.id = d.part_id(r, 0);
    d.claim_id("part", part.id, r.where(0));
    part.material_id = d.material_id(r, 1);
    part.where = r.where();
    unused_field(r, 2);
    // Shells need h given (checked once the mesh is in); hexahedra ignore it.
    if (r.given(3)) {
      part.thickness = r.number(3);
      r.require(part.thickness > 0.0, 3, "expected a thickness h > 0");
      d.parts_with_thickness.insert(part.id);
    }
    const double alpha_max = r.number_or(4, 0.0);
    r.require(alpha_max >= 0.0 && alpha_max <= 180.0, 4,
              "expected a smoothing angle in [0, 180] degrees (0: off)");
    if (alpha_max > 0.0) {
      PendingSmoothing s;
      s.entity = {EntityType::Part, part.id, r.where(0)};
      s.max_angle = alpha_max;
      d.smoothing.push_back(s);
    }
    part.erosion.min_step = r.number_or(5, 0.0);
    r.require(part.erosion.min_step >= 0.0, 5, "expected a time step >= 0 (0: off)");
    part.erosion.max_geometric_strain = r.number_or(6, 1e20);
    r.require(part.erosion.max_geometric_strain > 0.0, 6, "expected a strain > 0 (1e20: off)");
    part.erosion.max_volumetric_strain = r.number_or(7, 1e20);
    r.require(part.erosion.max_volumetric_strain > 0.0, 7, "expected a strain > 0 (1e20: off)");
    d.model.parts.push_back(part);
  }
}

void read_part_shell(DeckReader& d, Block& b) {
  if (b.done()) throw InputError(b.where(), "missing data line: expected pid, nip, q_hg");
  while (!b.done()) {
    const Row r = b.row({"pid", "nip", "q_hg"});
    PendingPartShell s;
    s.part = d.part_id(r, 0);
    s.where = r.where(0);
    d.claim_id("*PART_SHELL of part", s.part, s.where);
    const std::int64_t points = r.integer_or(1, ShellSection{}.points);
    r.require(points >= 1 && points <= 9 && points % 2 == 1, 1,
              "expected an odd number of integration points through the thickness, 1 to 9");
    s.points = static_cast<int>(points);
    s.hourglass = r.number_or(2, ShellSection{}.hourglass);
    r.require(s.hourglass >= 0.0, 2, "expected a hourglass coefficient >= 0");
    d.part_shells.push_back(s);
  }
}

}  // namespace abut::deck

namespace abut::deck {
namespace {

// Line 1 of *MAT_METAL and *MAT_JC: mid, rho, E, nu, did, thpid, eosid. The did is bound to its
// *PROP_DAMAGE_JC at the end of the deck (the material about to be added is the next one).
MetalParams metal_elasticity(DeckReader& d, const Row& r) {
  MetalParams p = isotropic_elasticity<MetalParams>(r, true);
  r.unsupported_unless(6, 0.0, "an equation of state (eosid)");
  if (r.given(4) && r.integer(4) != 0)
    d.damage_bindings.push_back({r.integer(4), r.where(4), d.model.materials.size()});
  return p;
}

// Thermal softening 1 - T*^m (metal.hpp): m = 0 (the default) is none; with m > 0 the melting
// temperature must lie above the reference one. Whether the material has a temperature field is
// the Simulation's check (it knows the thermal properties).
void thermal_softening(const Row& r, std::size_t m, std::size_t t0, std::size_t tm,
                       MetalParams& p) {
  p.softening_m = r.number_or(m, 0.0);
  r.require(p.softening_m >= 0.0, m, "expected a softening exponent m >= 0");
  p.room_temperature = r.number_or(t0, 0.0);
  p.melting_temperature = r.number_or(tm, 0.0);
  if (p.softens())
    r.require(p.melting_temperature > p.room_temperature, tm,
              "expected a melting temperature Tm above T0 (thermal softening, m > 0)");
}

}  // namespace

void read_mat_metal(DeckReader& d, Block& b) {
  const Row r1 = b.row({"mid", "rho", "E", "nu", "did", "thpid", "eosid"});
  const Row r2 = b.row({"cid", "xi", "yield", "c", "eps_dot0", "m", "T0", "Tm"});
  MetalParams p = metal_elasticity(d, r1);
  r2.unsupported_unless(1, 0.0, "kinematic hardening (xi)");
  r2.unsupported_unless(2, 0.0, "a yield surface other than von Mises (yield)");
  r2.unsupported_unless(3, 0.0, "rate hardening of *MAT_METAL (c; *MAT_JC has it)");
  if (r2.given(4)) r2.require(r2.number(4) > 0.0, 4, "expected a reference strain rate > 0");
  thermal_softening(r2, 5, 6, 7, p);
  if (auto r3 = b.optional_row({"s0", "s1", "eps_d", "mu"})) {
    for (std::size_t i = 0; i < 4; ++i)
      r3->unsupported_unless(i, 0.0, "the fields of line 3 (damage and friction)");
  }
  const std::size_t index = d.model.materials.size();
  d.bind_function(d.other_id(r2, 0), r2.where(0), [index](Model& model, FunctionRef f) {
    std::get<MetalParams>(model.materials[index].params).flow_curve = f;
  });
  add_material(d, r1, p, 5);
}

void read_mat_jc(DeckReader& d, Block& b) {
  const Row r1 = b.row({"mid", "rho", "E", "nu", "did", "thpid", "eosid"});
  const Row r2 = b.row({"A", "B", "n", "C", "m", "T0", "Tm", "eps_dot0"});
  MetalParams p = metal_elasticity(d, r1);
  p.johnson_cook = true;
  p.a = r2.number(0);
  r2.require(p.a > 0.0, 0, "expected an initial yield stress A > 0");
  p.b = r2.number_or(1, 0.0);
  r2.require(p.b >= 0.0, 1, "expected a hardening modulus B >= 0");
  p.n = r2.number_or(2, 1.0);
  r2.require(p.n > 0.0, 2, "expected a hardening exponent n > 0");
  p.c = r2.number_or(3, 0.0);
  r2.require(p.c >= 0.0, 3, "expected a rate coefficient C >= 0");
  thermal_softening(r2, 4, 5, 6, p);
  p.rate0 = r2.number_or(7, 1.0);
  r2.require(p.rate0 > 0.0, 7, "expected a reference strain rate > 0");
  if (auto r3 = b.optional_row({"-", "-", "d", "e"})) {
    for (std::size_t i = 0; i < 4; ++i) r3->unsupported_unless(i, 0.0, "the fields of line 3");
  }
  add_material(d, r1, p, 5);
}

// *PROP_DAMAGE_JC: did, d1, d2, d3, d4, d5, eps_dot0 (material.hpp, DuctileFailure).
void read_prop_damage_jc(DeckReader& d, Block& b) {
  if (b.done()) throw InputError(b.where(), "missing data line: expected did, d1, d2, d3, d4");
  while (!b.done()) {
    const Row r = b.row({"did", "d1", "d2", "d3", "d4", "d5", "eps_dot0"});
    const std::int64_t id = r.integer(0);
    r.require(id > 0, 0, "expected a damage property id > 0");
    d.claim_id("damage property", id, r.where(0));
    DuctileFailure f;
    f.active = true;
    f.d1 = r.number_or(1, 0.0);
    f.d2 = r.number_or(2, 0.0);
    f.d3 = r.number_or(3, 0.0);
    f.d4 = r.number_or(4, 0.0);
    r.require(f.d1 + f.d2 > 0.0, 1,
              "expected a failure strain d1 + d2 > 0 at zero triaxiality (d1 alone: a constant "
              "plastic failure strain)");
    f.d5 = r.number_or(5, 0.0);  // its material needs Tm > T0 and thermal properties
    f.rate0 = r.number_or(6, 1.0);
    r.require(f.rate0 > 0.0, 6, "expected a reference strain rate > 0");
    d.damage_properties[id] = f;
  }
}

}  // namespace abut::deck
