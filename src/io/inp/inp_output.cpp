// The output cards of Abaqus/CalculiX that choose what the states hold and how often: *NODE FILE,
// *EL FILE, *CONTACT FILE (CalculiX, the .frd file) and *OUTPUT, *NODE OUTPUT, *ELEMENT OUTPUT,
// *CONTACT OUTPUT (Abaqus, the .odb), into the model's OutputRequests (abut/model/output.hpp).
// As in CalculiX, a deck that asks for no field output writes none of its own choosing: abut then
// keeps its default, every field. The requests hold for the whole run (abut's states are one
// series): the union of the steps' keys, and the last FREQUENCY given.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "inp_reader.hpp"
#include "io/deck_text.hpp"

namespace abut::inp {

namespace {

using Kind = ParameterRule::Kind;

enum class Results { Node, Element, Contact };

// Each key abut's states hold, and the fields it stands for (CalculiX User's Manual, *NODE FILE
// and *EL FILE; Abaqus output variable identifiers).
const std::map<std::string, std::vector<std::string_view>>& fields_of(Results family) {
  static const std::map<std::string, std::vector<std::string_view>> node{
      {"U", {"displacement"}}, {"RF", {"force"}}, {"NT", {"temperature"}}, {"RFL", {"heat_flow"}}};
  static const std::map<std::string, std::vector<std::string_view>> element{
      {"S", {"stress", "von_mises_stress"}},
      {"PEEQ", {"plastic_strain"}},
      {"ENER", {"strain_energy"}},
      {"ELSE", {"strain_energy"}}};
  static const std::map<std::string, std::vector<std::string_view>> none;
  switch (family) {
    case Results::Node:
      return node;
    case Results::Element:
      return element;
    case Results::Contact:
      return none;
  }
  return none;
}

// FREQUENCY=n: a state every n-th increment of a step (and its last).
void read_frequency(Reader& r, const Card& c) {
  const auto frequency = parameter_value(c, "FREQUENCY");
  if (!frequency) return;
  const auto n = deck::parse_integer(*frequency);
  if (!n || *n < 1)
    throw InputError(r.where(c, "FREQUENCY"),
                     "expected FREQUENCY= an integer >= 1 (a state every n-th increment and at "
                     "each step's end), got '" +
                         *frequency + "'");
  r.model.output.state_frequency = static_cast<int>(*n);
}

// The keys of the card's data lines into the state fields; keys abut's states lack are noted.
void read_keys(Reader& r, const Card& c, Results family) {
  OutputRequests& o = r.model.output;
  if (!o.state_fields) o.state_fields.emplace();
  std::string left_out;
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (!f.given(i)) continue;
      const std::string key = deck::upper(f.text(i));
      const auto& known = fields_of(family);
      const auto it = known.find(key);
      if (it == known.end()) {
        left_out += (left_out.empty() ? "" : ", ") + key;
        continue;
      }
      for (const std::string_view field : it->second)
        if (std::find(o.state_fields->begin(), o.state_fields->end(), field) ==
            o.state_fields->end())
          o.state_fields->emplace_back(field);
    }
  }
  if (!left_out.empty())
    r.note(c, c.keyword + ": " + left_out +
                  " not written (abut's states hold displacement, force, temperature and heat "
                  "flow at the nodes, stress, plastic strain and strain energy per element; "
                  "contact results are in contact.csv and *CONTACT PRINT)");
}

// The parameters of the output cards that do not change abut's states, with why.
constexpr std::string_view kWholeMesh =
    "the states hold every node and element (select parts in ParaView): ignored";
constexpr std::string_view kNoEffect = "no effect on abut's states: ignored";

// The rules of a *NODE FILE or *EL FILE card: its own, then the parameters both take.
std::vector<ParameterRule> file_card_rules(std::initializer_list<ParameterRule> own) {
  std::vector<ParameterRule> rules{{"FREQUENCY"}};
  rules.insert(rules.end(), own);
  rules.insert(rules.end(),
               {{"GLOBAL", Kind::Ignored, kNoEffect},
                {"OUTPUT", Kind::Ignored, kNoEffect},
                {"LAST ITERATIONS", Kind::Ignored, kNoEffect},
                {"CONTACT ELEMENTS", Kind::Ignored, kNoEffect},
                {"TIME POINTS", Kind::Unsupported, "use FREQUENCY"},
                {"FREQUENCYF", Kind::Ignored, "applies to 3D fluid calculations: ignored"},
                {"VARIABLE", Kind::Ignored, kNoEffect}});
  return rules;
}

// Abaqus history output of a node set (after *OUTPUT, HISTORY): its nodes are followed in
// nodes.csv (position, displacement, nodal force), whatever keys the card lists.
void read_node_history(Reader& r, const Card& c) {
  check_parameters(r, c, {{"NSET"}, {"VARIABLE", Kind::Ignored, kNoEffect}});
  const auto set = parameter_value(c, "NSET");
  if (!set)
    throw InputError(r.where(c),
                     "*NODE OUTPUT after *OUTPUT, HISTORY needs NSET=: the node set whose "
                     "histories nodes.csv holds");
  r.history_node_sets.emplace_back(*set, r.loc(c));
  r.note(c, "*NODE OUTPUT, NSET=" + *set +
                " (history): nodes.csv holds its nodes' position, displacement and nodal force "
                "at every increment");
}

}  // namespace

void read_node_file(Reader& r, const Card& c) {
  if (r.history_output && c.key == "*NODEOUTPUT") return read_node_history(r, c);
  check_parameters(r, c, file_card_rules({{"NSET", Kind::Ignored, kWholeMesh}}));
  read_frequency(r, c);
  read_keys(r, c, Results::Node);
}

void read_el_file(Reader& r, const Card& c) {
  check_parameters(r, c,
                   file_card_rules({{"ELSET", Kind::Ignored, kWholeMesh},
                                    {"SECTION FORCES", Kind::Ignored, kNoEffect},
                                    {"POSITION", Kind::Ignored, kNoEffect},
                                    {"DIRECTIONS", Kind::Ignored, kNoEffect}}));
  read_frequency(r, c);
  read_keys(r, c, Results::Element);
}

void read_contact_file(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"FREQUENCY"},
                    {"LAST CONTACT FORCES", Kind::Ignored, kNoEffect},
                    {"TIME POINTS", Kind::Unsupported, "use FREQUENCY"},
                    {"VARIABLE", Kind::Ignored, kNoEffect}});
  read_frequency(r, c);
  read_keys(r, c, Results::Contact);
}

// Abaqus *OUTPUT, FIELD (or HISTORY): FREQUENCY applies to the states; after HISTORY, *NODE OUTPUT
// asks for the histories of its node set (nodes.csv), and the other requests are noted (abut
// writes its histories, energy.csv and contact.csv, at every increment).
void read_output(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"FIELD", Kind::Flag},
                    {"HISTORY", Kind::Flag},
                    {"FREQUENCY"},
                    {"OP", Kind::Ignored, kNoEffect},
                    {"VARIABLE", Kind::Ignored, kNoEffect},
                    {"NUMBER INTERVAL", Kind::Unsupported, "use FREQUENCY"},
                    {"TIME INTERVAL", Kind::Unsupported, "use FREQUENCY"},
                    {"TIME POINTS", Kind::Unsupported, "use FREQUENCY"}});
  r.history_output = find_parameter(c, "HISTORY") != nullptr;
  if (r.history_output) {
    r.note(c,
           "*OUTPUT, HISTORY: abut writes its histories (energy.csv, contact.csv, "
           "increments.csv, and nodes.csv for a *NODE OUTPUT, NSET=) at every increment");
    return;
  }
  read_frequency(r, c);
}

}  // namespace abut::inp
