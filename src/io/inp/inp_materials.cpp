// *MATERIAL with *ELASTIC, *DENSITY and *PLASTIC, the thermal properties abut skips, and *SOLID
// SECTION. Materials become Model::materials (ElasticParams) and sections parts in finish_mesh.
#include "inp_reader.hpp"

namespace abut::inp {
namespace {

MaterialRecord& current_material(Reader& r) { return r.materials[*r.material]; }

// The one data line of a material property; temperature tables are not supported yet.
const DataLine& property_line(const Reader& r, const Card& c, const std::string& what) {
  if (c.data.empty()) {
    throw InputError(r.where(c), "the data line with " + what + " is missing");
  }
  if (c.data.size() > 1) {
    throw InputError(r.where(Reader::loc(c.data[1]), c.keyword),
                     "temperature-dependent properties (several data lines) are not supported yet "
                     "by abut: give one line with " +
                         what);
  }
  return c.data.front();
}

}  // namespace

void read_material(Reader& r, const Card& c) {
  check_parameters(r, c, {{"NAME"}});
  no_data(r, c);
  const std::string name = required_parameter(r, c, "NAME");
  const auto [it, inserted] = r.material_names.emplace(upper_name(name), r.materials.size());
  if (!inserted) {
    throw InputError(r.where(c, "NAME"), "material " + name + " is already defined at " +
                                             r.at(r.materials[it->second].defined));
  }
  MaterialRecord m;
  m.name = name;
  m.defined = r.loc(c);
  r.materials.push_back(m);
  r.material = r.materials.size() - 1;
}

void read_elastic(Reader& r, const Card& c) {
  check_parameters(r, c, {{"TYPE"}});
  const std::string type = parameter_choice(
      r, c, "TYPE", {"ISO", "ORTHO", "ENGINEERING CONSTANTS", "ANISO", "ISOTROPIC"}, "ISO");
  if (type != "ISO" && type != "ISOTROPIC") {
    throw InputError(r.where(c, "TYPE"), "TYPE=" + type +
                                             " is not supported yet by abut: its elastic "
                                             "materials are isotropic (TYPE=ISO)");
  }
  const Fields f(r, c, property_line(r, c, "Young's modulus and Poisson's ratio"));
  f.at_most(3, "Young's modulus, Poisson's ratio, temperature");
  MaterialRecord& m = current_material(r);
  m.young = f.number(0, "E");
  m.poisson = f.number(1, "nu");
  if (!(m.young > 0.0)) f.fail("E", "expected Young's modulus > 0");
  if (!(m.poisson > -1.0 && m.poisson < 0.5)) {
    f.fail("nu", "expected Poisson's ratio in (-1, 0.5)");
  }
  m.elastic = true;
}

void read_density(Reader& r, const Card& c) {
  check_parameters(r, c, {});
  const Fields f(r, c, property_line(r, c, "the mass density"));
  f.at_most(2, "density, temperature");
  const double rho = f.number(0, "density");
  if (!(rho > 0.0)) f.fail("density", "expected a density > 0");
  current_material(r).density = rho;
}

// *PLASTIC, HARDENING=ISOTROPIC: lines of von Mises stress and equivalent plastic strain, the
// first at zero plastic strain (CalculiX User's Manual, *PLASTIC). Beyond the last point the
// stress stays constant, as in CalculiX.
void read_plastic(Reader& r, const Card& c) {
  check_parameters(r, c, {{"HARDENING"}});
  const std::string hardening =
      parameter_choice(r, c, "HARDENING",
                       {"ISOTROPIC", "KINEMATIC", "COMBINED", "USER", "JOHNSON COOK"}, "ISOTROPIC");
  if (hardening != "ISOTROPIC") {
    throw InputError(r.where(c, "HARDENING"), "HARDENING=" + hardening +
                                                  " is not supported yet by abut: its J2 "
                                                  "plasticity hardens isotropically");
  }
  if (c.data.empty()) {
    throw InputError(r.where(c), "the lines of yield stress and plastic strain are missing");
  }
  MaterialRecord& m = current_material(r);
  if (!m.flow_stress.empty()) {
    throw InputError(r.where(c), "material " + m.name + " already has a *PLASTIC card at " +
                                     r.at(m.plastic_defined));
  }
  m.plastic_defined = r.loc(c);
  std::optional<double> temperature;
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    f.at_most(3, "yield stress, plastic strain, temperature");
    const double stress = f.number(0, "yield stress");
    const double strain = f.number_or(1, "plastic strain", 0.0);
    if (!(stress > 0.0)) f.fail("yield stress", "expected a yield stress > 0");
    if (m.flow_stress.empty() && strain != 0.0) {
      f.fail("plastic strain", "the first line must be at plastic strain 0 (the initial yield)");
    }
    if (!m.plastic_strain.empty() && !(strain > m.plastic_strain.back())) {
      f.fail("plastic strain", "the plastic strains must increase from line to line");
    }
    if (f.given(2)) {
      const double t = f.number(2, "temperature");
      if (temperature && *temperature != t) {
        f.fail("temperature",
               "temperature-dependent hardening (several temperatures) is not supported yet by "
               "abut: give the curve of one temperature");
      }
      temperature = t;
    }
    m.flow_stress.push_back(stress);
    m.plastic_strain.push_back(strain);
  }
}

void read_thermal_property(Reader& r, const Card& c) {
  r.note(c,
         c.keyword + " is a thermal property: skipped (abut solves the mechanical problem only)");
}

void read_solid_section(Reader& r, const Card& c) {
  check_parameters(
      r, c,
      {{"ELSET"},
       {"MATERIAL"},
       {"ORIENTATION", ParameterRule::Kind::Unsupported,
        "local material axes matter for anisotropic materials, which abut does not have"},
       {"CONTROLS", ParameterRule::Kind::Unsupported, "section controls"}});
  SectionRecord s;
  s.elset = required_parameter(r, c, "ELSET");
  s.material = required_parameter(r, c, "MATERIAL");
  s.where = r.loc(c);
  if (c.data.size() > 1) {
    throw InputError(r.where(Reader::loc(c.data[1]), c.keyword),
                     "unexpected data line: *SOLID SECTION takes at most one (the thickness)");
  }
  if (!c.data.empty()) {
    r.note(c,
           "the thickness under *SOLID SECTION applies to plane and truss elements only: "
           "ignored for the hexahedra of " +
               s.elset);
  }
  r.sections.push_back(s);
}

}  // namespace abut::inp
