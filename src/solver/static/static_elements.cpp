#include "solver/static/static_elements.hpp"

#include <cmath>
#include <string>
#include <variant>

#include "abut/core/error.hpp"
#include "abut/element/hex8.hpp"
#include "abut/element/hex8_reduced.hpp"

namespace abut::detail {

StaticElements::StaticElements(const Model& model) : model_(model) {
  const Mesh& mesh = model.mesh;
  if (mesh.shell_count() > 0)
    throw InputError("the static solver does not support shells yet (" +
                     std::to_string(mesh.shell_count()) + " in the model)");
  for (const Part& part : model.parts) {
    bool used = false;
    for (std::size_t h = 0; h < mesh.hex_count() && !used; ++h) used = mesh.hex_part[h] == part.id;
    if (!used) continue;
    const MaterialParams& m = model.material_of_part(part.id);
    if (!std::holds_alternative<ElasticParams>(m) && !std::holds_alternative<MetalParams>(m))
      throw InputError(part.where, "part " + std::to_string(part.id) + " (" + part.title +
                                       "): the static solver supports linear elastic and J2 "
                                       "plastic materials (*ELASTIC, *PLASTIC, *MAT_ELASTIC, "
                                       "*MAT_METAL, *MAT_JC) only yet");
    if (const auto* metal = std::get_if<MetalParams>(&m); metal && metal->failure.active)
      throw InputError(part.where, "part " + std::to_string(part.id) + " (" + part.title +
                                       "): ductile failure (*PROP_DAMAGE_JC) is not supported in "
                                       "static steps yet");
    if (const auto* metal = std::get_if<MetalParams>(&m); metal && metal->softens())
      throw InputError(part.where, "part " + std::to_string(part.id) + " (" + part.title +
                                       "): thermal softening (m > 0) is not supported in static "
                                       "steps yet (the temperature does not act back on the "
                                       "static mechanics): give m = 0");
  }
  hexes_ = mesh.hexes;
  ids_ = mesh.hex_id;
  const std::size_t n = hexes_.size();
  reduced_.resize(n);
  elastic_.reserve(n);
  plastic_.assign(n, nullptr);
  hourglass_modulus_.resize(n);
  for (std::size_t h = 0; h < n; ++h) {
    const Part& part = *model.find_part(mesh.hex_part[h]);
    const MaterialParams& m = model.material_of_part(part.id);
    if (const auto* e = std::get_if<ElasticParams>(&m)) {
      elastic_.push_back({e->young, e->poisson});
    } else {
      const auto& metal = std::get<MetalParams>(m);
      elastic_.push_back({metal.young, metal.poisson});
      plastic_[h] = &metal;
    }
    reduced_[h] = part.solid_integration == Part::SolidIntegration::OnePoint ? 1 : 0;
    const double shear = elastic_.back().young / (2.0 * (1.0 + elastic_.back().poisson));
    hourglass_modulus_[h] = kHex8HourglassCoefficient * 2.0 * shear;
  }
  committed_.resize(8 * n);
  trial_.resize(8 * n);
  force_.resize(24 * n);
  stiffness_.resize(576 * n);
  stress_.resize(48 * n);
  strain_.resize(48 * n);
  energy_.resize(n);
  plastic_strain_.resize(8 * n);
  energy_density_.resize(8 * n);
  volume_.resize(n);
}

void StaticElements::evaluate(std::span<const double> u, bool nonlinear_geometry) {
  const Nodes& nodes = model_.mesh.nodes;
  const auto n = static_cast<std::int64_t>(hexes_.size());
  std::int64_t inverted = -1;
#pragma omp parallel
  {
    Hex8FullInput in;
    Hex8FullResult out;
    in.nonlinear_geometry = nonlinear_geometry;
#pragma omp for schedule(static)
    for (std::int64_t e = 0; e < n; ++e) {
      for (int a = 0; a < 8; ++a) {
        const std::size_t node = static_cast<std::size_t>(hexes_[e][a]);
        in.X[a][0] = nodes.x[node];
        in.X[a][1] = nodes.y[node];
        in.X[a][2] = nodes.z[node];
        for (int k = 0; k < 3; ++k) in.u[a][k] = u[3 * node + k];
      }
      const auto run = [&](const auto& material) {
        if (reduced_[e])
          hex8_reduced_with(in, material, hourglass_modulus_[e], out);
        else
          hex8_full_with(in, material, out);
      };
      if (plastic_[e] != nullptr) {
        const J2StrainPoint point{elastic_[e].young, elastic_[e].poisson,
                                  FlowStress(*plastic_[e], &model_.functions), &committed_[8 * e],
                                  &trial_[8 * e]};
        run(point);
      } else {
        run(elastic_[e]);
      }
      if (!(out.min_jacobian > 0.0)) {
#pragma omp critical(abut_static_inverted)
        if (inverted < 0 || e < inverted) inverted = e;
      }
      std::copy(out.force, out.force + 24, &force_[24 * e]);
      std::copy(out.stiffness, out.stiffness + 576, &stiffness_[576 * e]);
      for (int p = 0; p < 8; ++p) {
        for (int k = 0; k < 6; ++k) {
          stress_[48 * e + 6 * p + k] = out.stress[p][k];
          strain_[48 * e + 6 * p + k] = out.strain[p][k];
        }
        const int point = reduced_[e] ? 0 : p;
        plastic_strain_[8 * e + p] = trial_[8 * e + point].equivalent_plastic_strain;
        energy_density_[8 * e + p] = out.energy_density[p];
      }
      energy_[e] = out.strain_energy;
      volume_[e] = out.volume;
    }
  }
  if (inverted >= 0)
    throw InstabilityError("element " + std::to_string(ids_[inverted]) +
                           " turned inside out (det J <= 0 at a Gauss point): the load increment "
                           "is too large or the model lacks support");
}

double StaticElements::force_magnitude_sum() const {
  double sum = 0.0;
  for (const double v : force_) sum += std::abs(v);
  return sum;
}

void StaticElements::add_forces(std::span<double> f) const {
  for (std::size_t e = 0; e < hexes_.size(); ++e)
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k) f[3 * hexes_[e][a] + k] += force_[24 * e + 3 * a + k];
}

}  // namespace abut::detail
