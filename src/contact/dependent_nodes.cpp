#include "abut/contact/dependent_nodes.hpp"

#include <stdexcept>
#include <string>

namespace abut {

std::int32_t DependentNodes::add(std::span<const std::int32_t> nodes,
                                 std::span<const double> weights) {
  node.insert(node.end(), nodes.begin(), nodes.end());
  weight.insert(weight.end(), weights.begin(), weights.end());
  start.push_back(static_cast<std::int32_t>(node.size()));
  if (!offset.empty()) offset.resize(3 * size(), 0.0);
  return first + static_cast<std::int32_t>(size()) - 1;
}

void DependentNodes::extend(std::span<const double> x, std::span<const double> y,
                            std::span<const double> z, std::vector<double>& ex,
                            std::vector<double>& ey, std::vector<double>& ez) const {
  const auto host = static_cast<std::size_t>(first);
  if (x.size() != host || y.size() != host || z.size() != host)
    throw std::invalid_argument("DependentNodes: the host has " + std::to_string(x.size()) +
                                " nodes, the dependent nodes were made for " +
                                std::to_string(host));
  ex.assign(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(host));
  ey.assign(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(host));
  ez.assign(z.begin(), z.begin() + static_cast<std::ptrdiff_t>(host));
  for (std::size_t k = 0; k < size(); ++k) {
    double px = 0.0, py = 0.0, pz = 0.0;
    for (auto t = static_cast<std::size_t>(start[k]); t < static_cast<std::size_t>(start[k + 1]);
         ++t) {
      const auto a = static_cast<std::size_t>(node[t]);
      px += weight[t] * x[a], py += weight[t] * y[a], pz += weight[t] * z[a];
    }
    if (!offset.empty()) px += offset[3 * k], py += offset[3 * k + 1], pz += offset[3 * k + 2];
    ex.push_back(px), ey.push_back(py), ez.push_back(pz);
  }
}

ContactWeights DependentNodes::expand(const ContactWeights& w) const {
  if (empty()) return w;
  ContactWeights out;
  for (int k = 0; k < w.count; ++k) {
    if (w.nodes[k] < first) {
      out.add(w.nodes[k], w.weights[k]);
      continue;
    }
    const auto d = static_cast<std::size_t>(w.nodes[k] - first);
    for (auto t = static_cast<std::size_t>(start[d]); t < static_cast<std::size_t>(start[d + 1]);
         ++t)
      out.add(node[t], w.weights[k] * weight[t]);
  }
  return out;
}

}  // namespace abut
