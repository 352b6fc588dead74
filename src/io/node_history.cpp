// nodes.csv (node_history.hpp).
#include "node_history.hpp"

#include <string>

#include "abut/solver/simulation.hpp"

namespace abut {

NodeHistory::NodeHistory(const std::filesystem::path& dir, const Model& model, Run run)
    : model_(model), nodes_(model.history_nodes()) {
  if (nodes_.empty()) return;
  std::vector<std::string> columns{"node", "x", "y", "z", "ux", "uy", "uz"};
  if (run == Run::Explicit)
    columns.insert(columns.end(),
                   {"vx", "vy", "vz", "contact_force_x", "contact_force_y", "contact_force_z"});
  else
    columns.insert(columns.end(), {"force_x", "force_y", "force_z"});
  csv_.emplace(dir / "nodes.csv", std::move(columns));
}

void NodeHistory::write(const Simulation& sim) {
  if (!csv_) return;
  const bool contact = sim.has_contact();
  if (contact) sim.contact_fields(contact_force_, contact_pressure_, wear_);
  const Nodes& ref = model_.mesh.nodes;
  for (const std::int32_t n : nodes_) {
    const auto i = static_cast<std::size_t>(n);
    const double x = sim.x()[i], y = sim.y()[i], z = sim.z()[i];
    row_ = {ref.id[i],
            x,
            y,
            z,
            x - ref.x[i],
            y - ref.y[i],
            z - ref.z[i],
            sim.vx()[i],
            sim.vy()[i],
            sim.vz()[i],
            contact ? contact_force_[3 * i] : 0.0,
            contact ? contact_force_[3 * i + 1] : 0.0,
            contact ? contact_force_[3 * i + 2] : 0.0};
    csv_->write_row(sim.time(), row_);
  }
}

void NodeHistory::write(double time, std::span<const double> u, std::span<const double> f) {
  if (!csv_) return;
  const Nodes& ref = model_.mesh.nodes;
  for (const std::int32_t n : nodes_) {
    const auto i = static_cast<std::size_t>(n);
    row_ = {ref.id[i],
            ref.x[i] + u[3 * i],
            ref.y[i] + u[3 * i + 1],
            ref.z[i] + u[3 * i + 2],
            u[3 * i],
            u[3 * i + 1],
            u[3 * i + 2],
            f[3 * i],
            f[3 * i + 1],
            f[3 * i + 2]};
    csv_->write_row(time, row_);
  }
}

}  // namespace abut
