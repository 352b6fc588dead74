#pragma once
// What a run writes and how often, whatever the input language asked for it (IMPETUS *OUTPUT and
// abut's *OUTPUT_FIELDS and *OUTPUT_NODE_HISTORY; Abaqus/CalculiX *NODE FILE, *EL FILE, *OUTPUT
// and their FREQUENCY). The defaults are abut's outputs: every field the run has, states at 1/100
// of an explicit run and at every converged static increment, histories at 1/1000 of an explicit
// run, no node histories.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "abut/model/entity.hpp"

namespace abut {

// Every field a state (VTU) may hold, by the name it has in ParaView. Explicit runs: displacement,
// velocity, contact_force, contact_pressure, wear, temperature, heat_flow at the nodes; part_id,
// thickness, von_mises_stress, pressure, plastic_strain, plastic_strain_rate per cell. Static runs:
// displacement, force, temperature, heat_flow; part_id, stress, von_mises_stress, plastic_strain,
// strain_energy. part_id is always written (ParaView's filters select parts by it).
inline constexpr std::string_view kStateFields[] = {
    "displacement", "velocity",         "force",     "contact_force",  "contact_pressure",
    "wear",         "temperature",      "heat_flow", "part_id",        "thickness",
    "stress",       "von_mises_stress", "pressure",  "plastic_strain", "plastic_strain_rate",
    "strain_energy"};

// Whether `name` is one of kStateFields.
bool is_state_field(std::string_view name);

struct OutputRequests {
  double state_interval = 0.0;    // explicit runs [time]; 0: the run's span / 100
  double history_interval = 0.0;  // explicit runs [time]; 0: the run's span / 1000
  int state_frequency = 1;        // static runs: every n-th increment of a step, and its last
  // The fields of the states (kStateFields); none chosen: every field the run has.
  std::optional<std::vector<std::string>> state_fields;
  // The nodes whose motion nodes.csv follows at every history output (explicit) or converged
  // increment (static), in the input's order; none: no nodes.csv. Model::history_nodes resolves
  // them to a sorted node list.
  std::vector<EntityRef> history_nodes;

  // Whether the states carry `field`.
  bool writes(std::string_view field) const;
};

}  // namespace abut
