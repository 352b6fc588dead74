#include "solver/static/static_elements.hpp"

#include <cmath>
#include <string>
#include <variant>

#include "abut/core/error.hpp"
#include "abut/element/hex8.hpp"
#include "abut/element/hex8_reduced.hpp"
#include "abut/element/solid_full.hpp"

namespace abut::detail {

StaticElements::StaticElements(const Model& model) : model_(model) {
  const Mesh& mesh = model.mesh;
  if (mesh.shell_count() > 0)
    throw InputError("the static solver does not support shells yet (" +
                     std::to_string(mesh.shell_count()) + " in the model)");
  for (const Part& part : model.parts) {
    bool used = false;
    for (std::size_t e = 0; e < mesh.solid_count() && !used; ++e)
      used = mesh.solid(e).part == part.id;
    if (!used) continue;
    const MaterialParams& m = model.material_of_part(part.id);
    if (!std::holds_alternative<ElasticParams>(m) && !std::holds_alternative<MetalParams>(m))
      throw InputError(part.where, "part " + std::to_string(part.id) + " (" + part.title +
                                       "): the static solver supports " +
                                       model.sources.words("static_materials") + " only yet");
    if (const auto* metal = std::get_if<MetalParams>(&m); metal && metal->failure.active)
      throw InputError(part.where, "part " + std::to_string(part.id) + " (" + part.title +
                                       "): " + model.sources.words("ductile_failure") +
                                       " is not supported in "
                                       "static steps yet");
    if (const auto* metal = std::get_if<MetalParams>(&m); metal && metal->softens())
      throw InputError(part.where, "part " + std::to_string(part.id) + " (" + part.title +
                                       "): thermal softening (m > 0) is not supported in static "
                                       "steps yet (the temperature does not act back on the "
                                       "static mechanics): give m = 0");
  }
  const std::size_t n = mesh.solid_count();
  types_.resize(n);
  ids_.resize(n);
  reduced_.resize(n);
  elastic_.reserve(n);
  plastic_.assign(n, nullptr);
  hourglass_modulus_.resize(n);
  node_start_.assign(n + 1, 0);
  point_start_.assign(n + 1, 0);
  stiffness_start_.assign(n + 1, 0);
  for (std::size_t e = 0; e < n; ++e) {
    const SolidRef solid = mesh.solid(e);
    const Part& part = *model.find_part(solid.part);
    const MaterialParams& m = model.material_of_part(part.id);
    if (const auto* el = std::get_if<ElasticParams>(&m)) {
      elastic_.push_back({el->young, el->poisson});
    } else {
      const auto& metal = std::get<MetalParams>(m);
      elastic_.push_back({metal.young, metal.poisson});
      plastic_[e] = &metal;
    }
    types_[e] = solid.type;
    ids_[e] = solid.id;
    nodes_.insert(nodes_.end(), solid.nodes.begin(), solid.nodes.end());
    reduced_[e] = part.solid_integration == Part::SolidIntegration::Reduced &&
                  !quadrature(solid.type, Integration::reduced).empty();
    const std::size_t dofs = 3 * solid.nodes.size();
    node_start_[e + 1] = node_start_[e] + solid.nodes.size();
    point_start_[e + 1] = point_start_[e] + rule(e).size();
    stiffness_start_[e + 1] = stiffness_start_[e] + dofs * dofs;
    const double shear = elastic_.back().young / (2.0 * (1.0 + elastic_.back().poisson));
    hourglass_modulus_[e] = kHex8HourglassCoefficient * 2.0 * shear;
  }
  const std::size_t points = point_start_[n];
  committed_.resize(points);
  trial_.resize(points);
  force_.resize(3 * node_start_[n]);
  stiffness_.resize(stiffness_start_[n]);
  stress_.resize(6 * points);
  strain_.resize(6 * points);
  energy_.resize(n);
  plastic_strain_.resize(points);
  energy_density_.resize(points);
  volume_.resize(n);
}

std::span<const QuadraturePoint> StaticElements::rule(std::size_t e) const {
  return quadrature(types_[e], reduced_[e] ? Integration::reduced : Integration::full);
}

void StaticElements::evaluate(std::span<const double> u, bool nonlinear_geometry) {
  const Nodes& mesh_nodes = model_.mesh.nodes;
  const auto n = static_cast<std::int64_t>(types_.size());
  std::int64_t inverted = -1;
#pragma omp parallel
  {
    Hex8FullInput in;
    Hex8FullResult out;
    in.nonlinear_geometry = nonlinear_geometry;
    SolidElementResult solid;
    std::vector<double> X, ue;
#pragma omp for schedule(static)
    for (std::int64_t e = 0; e < n; ++e) {
      const auto el = static_cast<std::size_t>(e);
      const std::span<const std::int32_t> cell = nodes(el);
      const std::size_t p0 = point_start_[el];
      J2PointHistory* trial = &trial_[p0];
      const auto run = [&](const auto& material) {
        if (types_[el] != CellType::hex8) {
          X.resize(3 * cell.size());
          ue.resize(3 * cell.size());
          for (std::size_t a = 0; a < cell.size(); ++a) {
            const auto node = static_cast<std::size_t>(cell[a]);
            X[3 * a] = mesh_nodes.x[node];
            X[3 * a + 1] = mesh_nodes.y[node];
            X[3 * a + 2] = mesh_nodes.z[node];
            for (std::size_t k = 0; k < 3; ++k) ue[3 * a + k] = u[3 * node + k];
          }
          solid_full_with({types_[el], rule(el), X, ue, nonlinear_geometry}, material, solid);
          return;
        }
        for (int a = 0; a < 8; ++a) {
          const auto node = static_cast<std::size_t>(cell[static_cast<std::size_t>(a)]);
          in.X[a][0] = mesh_nodes.x[node];
          in.X[a][1] = mesh_nodes.y[node];
          in.X[a][2] = mesh_nodes.z[node];
          for (int k = 0; k < 3; ++k) in.u[a][k] = u[3 * node + static_cast<std::size_t>(k)];
        }
        if (reduced_[el])
          hex8_reduced_with(in, material, hourglass_modulus_[el], out);
        else
          hex8_full_with(in, material, out);
        // The hexahedron's fixed-size result into the element's slots of the general one.
        const int points = integration_points(el);
        solid.force.assign(out.force, out.force + 24);
        solid.stiffness.assign(out.stiffness, out.stiffness + 576);
        solid.stress.resize(6 * static_cast<std::size_t>(points));
        solid.strain.resize(6 * static_cast<std::size_t>(points));
        solid.energy_density.resize(static_cast<std::size_t>(points));
        for (int p = 0; p < points; ++p) {
          std::copy(out.stress[p], out.stress[p] + 6,
                    &solid.stress[6 * static_cast<std::size_t>(p)]);
          std::copy(out.strain[p], out.strain[p] + 6,
                    &solid.strain[6 * static_cast<std::size_t>(p)]);
          solid.energy_density[static_cast<std::size_t>(p)] = out.energy_density[p];
        }
        solid.strain_energy = out.strain_energy;
        solid.volume = out.volume;
        solid.min_jacobian = out.min_jacobian;
      };
      if (plastic_[el] != nullptr) {
        const J2StrainPoint point{elastic_[el].young, elastic_[el].poisson,
                                  FlowStress(*plastic_[el], &model_.functions), &committed_[p0],
                                  trial};
        run(point);
      } else {
        run(elastic_[el]);
      }
      if (!(solid.min_jacobian > 0.0)) {
#pragma omp critical(abut_static_inverted)
        if (inverted < 0 || e < inverted) inverted = e;
      }
      std::copy(solid.force.begin(), solid.force.end(), &force_[3 * node_start_[el]]);
      std::copy(solid.stiffness.begin(), solid.stiffness.end(), &stiffness_[stiffness_start_[el]]);
      std::copy(solid.stress.begin(), solid.stress.end(), &stress_[6 * p0]);
      std::copy(solid.strain.begin(), solid.strain.end(), &strain_[6 * p0]);
      std::copy(solid.energy_density.begin(), solid.energy_density.end(), &energy_density_[p0]);
      for (std::size_t p = 0; p < solid.energy_density.size(); ++p)
        plastic_strain_[p0 + p] = trial[p].equivalent_plastic_strain;
      energy_[el] = solid.strain_energy;
      volume_[el] = solid.volume;
    }
  }
  if (inverted >= 0)
    throw InstabilityError("element " + std::to_string(ids_[static_cast<std::size_t>(inverted)]) +
                           " turned inside out (det J <= 0 at a Gauss point): the load increment "
                           "is too large or the model lacks support");
}

double StaticElements::force_magnitude_sum() const {
  double sum = 0.0;
  for (const double v : force_) sum += std::abs(v);
  return sum;
}

void StaticElements::add_forces(std::span<double> f) const {
  for (std::size_t e = 0; e < types_.size(); ++e) {
    const std::span<const std::int32_t> cell = nodes(e);
    const double* fe = force(e);
    for (std::size_t a = 0; a < cell.size(); ++a)
      for (std::size_t k = 0; k < 3; ++k)
        f[3 * static_cast<std::size_t>(cell[a]) + k] += fe[3 * a + k];
  }
}

}  // namespace abut::detail
