#pragma once
// nodes.csv: the motion of the nodes the output requests follow (OutputRequests::history_nodes;
// .k *OUTPUT_NODE_HISTORY), one row per node at each output, the node by its user id. Explicit
// runs write position, displacement, velocity and the contact force at each history output;
// static runs position, displacement and the nodal force (loads and reactions) at each converged
// increment. Without followed nodes there is no file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

#include "abut/core/state_archive.hpp"
#include "abut/io/csv_history.hpp"
#include "abut/model/model.hpp"

namespace abut {

class Simulation;

class NodeHistory {
 public:
  enum class Run { Explicit, Static };
  // InputError at the entity's place when a followed node, set or part does not exist.
  NodeHistory(const std::filesystem::path& dir, const Model& model, Run run);

  // Explicit runs: at the simulation's time.
  void write(const Simulation& sim);
  // Static runs: the converged displacement u and nodal force f (3 per node, node-major).
  void write(double time, std::span<const double> u, std::span<const double> f);
  void archive(StateArchive& a) { a.value(csv_); }

 private:
  const Model& model_;
  std::vector<std::int32_t> nodes_;
  std::optional<CsvHistory> csv_;
  std::vector<double> contact_force_, contact_pressure_, wear_;
  std::vector<CsvHistory::Value> row_;
};

}  // namespace abut
