#include "abut/mesh/node_removal.hpp"

#include <algorithm>
#include <stdexcept>

#include "mesh/node_merger.hpp"

namespace abut {

std::vector<std::int32_t> coincident_replacements(const Nodes& nodes,
                                                  const std::vector<std::int32_t>& secondary,
                                                  const std::vector<std::int32_t>& main,
                                                  double tolerance) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("coincident_replacements: tolerance <= 0");
  std::vector<std::uint8_t> in_main(nodes.size(), 0);
  detail::NodeMerger candidates(tolerance);
  for (const std::int32_t m : main) {
    in_main[static_cast<std::size_t>(m)] = 1;
    candidates.insert(m, nodes.position(static_cast<std::size_t>(m)));
  }
  std::vector<std::int32_t> replacement(nodes.size(), -1);
  for (const std::int32_t s : secondary) {
    const auto i = static_cast<std::size_t>(s);
    // A node of both entities is a node of the surface merged onto: it stays.
    if (in_main[i]) continue;
    replacement[i] = candidates.nearest(nodes.position(i));
  }
  return replacement;
}

std::vector<std::int32_t> coincident_replacements(const Nodes& nodes,
                                                  const std::vector<std::int32_t>& secondary,
                                                  const std::vector<std::int32_t>& main,
                                                  const std::vector<double>& tolerance) {
  if (tolerance.size() != nodes.size())
    throw std::invalid_argument("coincident_replacements: one tolerance per node expected");
  double largest = 0.0;
  for (const auto& entity : {secondary, main}) {
    for (const std::int32_t n : entity) {
      const double t = tolerance[static_cast<std::size_t>(n)];
      if (!(t > 0.0)) throw std::invalid_argument("coincident_replacements: tolerance <= 0");
      largest = std::max(largest, t);
    }
  }
  std::vector<std::int32_t> replacement(nodes.size(), -1);
  if (secondary.empty() || main.empty()) return replacement;
  std::vector<std::uint8_t> in_main(nodes.size(), 0);
  detail::NodeMerger candidates(largest);
  for (const std::int32_t m : main) {
    in_main[static_cast<std::size_t>(m)] = 1;
    candidates.insert(m, nodes.position(static_cast<std::size_t>(m)));
  }
  for (const std::int32_t s : secondary) {
    const auto i = static_cast<std::size_t>(s);
    if (in_main[i]) continue;
    const double own = tolerance[i];
    replacement[i] = candidates.nearest(nodes.position(i), [&](std::int32_t m, double d) {
      return d <= std::min(own, tolerance[static_cast<std::size_t>(m)]);
    });
  }
  return replacement;
}

std::vector<std::int32_t> remove_nodes(Mesh& mesh, const std::vector<std::int32_t>& replacement) {
  Nodes& nodes = mesh.nodes;
  if (replacement.size() != nodes.size())
    throw std::invalid_argument("remove_nodes: one replacement per node expected");
  for (const std::int32_t r : replacement) {
    if (r >= 0 && (static_cast<std::size_t>(r) >= nodes.size() ||
                   replacement[static_cast<std::size_t>(r)] >= 0))
      throw std::invalid_argument("remove_nodes: a node is replaced by a removed node");
  }
  std::vector<std::int32_t> new_index(nodes.size(), -1);
  std::int32_t kept = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (replacement[i] < 0) new_index[i] = kept++;
  }
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (replacement[i] < 0) continue;
    const auto survivor = static_cast<std::size_t>(replacement[i]);
    new_index[i] = new_index[survivor];
    nodes.fixed[survivor] |= nodes.fixed[i];
  }

  Nodes compact;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (replacement[i] < 0) compact.add(nodes.id[i], nodes.position(i), nodes.fixed[i]);
  }
  nodes = std::move(compact);
  const auto remap = [&](auto& elements) {
    for (auto& element : elements)
      for (std::int32_t& n : element) n = new_index[static_cast<std::size_t>(n)];
  };
  remap(mesh.hexes);
  remap(mesh.shells);
  for (CellBlock& block : mesh.cells)
    for (std::int32_t& n : block.nodes) n = new_index[static_cast<std::size_t>(n)];
  return new_index;
}

}  // namespace abut
