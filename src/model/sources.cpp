// The places of the model's settings in the input, and the words for them (sources.hpp).
#include "abut/model/sources.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

namespace abut {

namespace {

// Every setting that has a place of its own, by entity. A contact's are the contact library's
// names (ContactSettings members and the settings of its ContactSetupError) and, after them, the
// model's own (ContactSpec members that the library has not).
constexpr std::string_view kContactSettings[] = {
    "accuracy_level", "accuracy_edge", "adhesion", "begin_time", "clearance", "damping",
    "detection_depth", "discretisation", "edge_angle", "edge_tolerance", "edges", "end_time",
    "erosion", "freeze", "friction_filter", "gaps", "initial_max", "initial_offset", "memory",
    "normal_law", "one_way", "pair_frictions", "pair_scales", "regions", "search_margin",
    "secondary_nodes", "sense", "stick_stress", "stiffness", "surface", "surface1", "surface2",
    "tangential_law", "tangential_penalty", "thermal", "tool", "wear",
    // the model's own
    "adjust", "conductance", "dependencies", "friction_heat", "initial_penetration", "penalty",
    "release_bc", "sensor", "shell_sides", "small_sliding", "symmetric"};
constexpr std::string_view kTieSettings[] = {"exact", "detection_depth", "edge_tolerance",
                                             "edge_angle"};
constexpr std::string_view kTimeSettings[] = {"min_step", "max_step"};

// The model's words for the concepts a message may ask the user to give; a reader replaces them
// by its language's (Sources::name).
constexpr std::pair<std::string_view, std::string_view> kModelWords[] = {
    {"analytic_tool", "an analytic tool"},
    {"boundary_condition", "a boundary condition"},
    {"conductance_function", "the contact's conductance function"},
    {"detection_depth", "the contact's detection depth"},
    {"ductile_failure", "ductile failure"},
    {"initial_velocity", "the initial velocity"},
    {"linear_constraint", "linear constraint"},
    {"max_increments", "the maximum number of increments"},
    {"max_step", "the maximum time step"},
    {"min_step", "the minimum time step"},
    {"pair_penalty_scale", "a penalty scale factor of the part pair"},
    {"penalty", "the contact's penalty stiffness"},
    {"rigid_motion", "a motion of the rigid part as a whole"},
    {"static_materials", "linear elastic and J2 plastic materials"},
    {"thermal_properties", "thermal properties"},
    {"tie_by_penalty", "a penalty tie"},
    {"unit_system", "the unit system"},
};

void check_setting(SourceEntity entity, std::string_view setting) {
  if (!Sources::has_setting(entity, setting))
    throw std::logic_error("Sources: no setting '" + std::string(setting) + "' here");
}

std::string_view model_words(std::string_view concept_name) {
  for (const auto& [name, words] : kModelWords)
    if (name == concept_name) return words;
  throw std::logic_error("Sources: no concept '" + std::string(concept_name) + "'");
}

}  // namespace

std::span<const std::string_view> Sources::settings(SourceEntity entity) {
  switch (entity) {
    case SourceEntity::Contact:
      return kContactSettings;
    case SourceEntity::Tie:
      return kTieSettings;
    case SourceEntity::Time:
      return kTimeSettings;
  }
  return {};
}

bool Sources::has_setting(SourceEntity entity, std::string_view setting) {
  const std::span<const std::string_view> names = settings(entity);
  return std::find(names.begin(), names.end(), setting) != names.end();
}

void Sources::set(SourceEntity entity, std::int64_t id, std::string_view setting,
                  SourceLocation where) {
  check_setting(entity, setting);
  places_.insert_or_assign(std::tuple{entity, id, std::string(setting)}, std::move(where));
}

bool Sources::given(SourceEntity entity, std::int64_t id, std::string_view setting) const {
  check_setting(entity, setting);
  return places_.find(std::tuple{entity, id, std::string(setting)}) != places_.end();
}

SourceLocation Sources::of(SourceEntity entity, std::int64_t id, std::string_view setting,
                           const SourceLocation& otherwise) const {
  check_setting(entity, setting);
  const auto it = places_.find(std::tuple{entity, id, std::string(setting)});
  return it == places_.end() ? otherwise : it->second;
}

void Sources::name(std::string_view concept_name, std::string words) {
  model_words(concept_name);  // a known concept
  words_.insert_or_assign(std::string(concept_name), std::move(words));
}

std::string Sources::words(std::string_view concept_name) const {
  const auto it = words_.find(concept_name);
  return it == words_.end() ? std::string(model_words(concept_name)) : it->second;
}

}  // namespace abut
