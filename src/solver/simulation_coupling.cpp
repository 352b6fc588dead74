// Coupling of the mechanics to the temperature field (issue 11): thermal expansion and softening
// in the elements (SolidBlock::set_thermal), and the Taylor-Quinney heat of the plastic work.
#include <string>

#include "simulation_impl.hpp"

namespace abut {

namespace {

std::string material_name(const Material& m) { return "material " + std::to_string(m.id); }

}  // namespace

// Gives each deformable block the thermal properties of its material. Softening needs a
// temperature, so a softening metal without thermal properties is an input error at the
// material; shells do not take the temperature yet.
void Simulation::Impl::couple_heat() {
  taylor_quinney.assign(blocks.size(), 0.0);
  bool any = false;
  for (const PartInfo& info : parts) {
    if (info.rigid) continue;
    const Material& material = *model.find_material(model.find_part(info.part_id)->material_id);
    const auto* metal = std::get_if<MetalParams>(&material.params);
    const bool softens = metal != nullptr && metal->thermal();  // softening or d5
    const ThermalProperties* props =
        material.thermal_id != 0 ? model.thermal.find(material.thermal_id) : nullptr;
    // Shells conduct heat (shell4_thermal.hpp) but do not take the temperature back yet.
    if (info.shell_block >= 0 && (softens || (props != nullptr && props->expansion != 0.0)))
      throw InputError(material.where, material_name(material) + " of part " +
                                           std::to_string(info.part_id) +
                                           ": thermal expansion, softening and the failure "
                                           "strain's d5 of shells are not supported yet");
    if (info.shell_block >= 0 && metal != nullptr && props != nullptr &&
        props->taylor_quinney > 0.0)
      throw InputError(material.where, material_name(material) + " of part " +
                                           std::to_string(info.part_id) +
                                           ": the plastic heat of shells (Taylor-Quinney) is not "
                                           "supported yet: give the thermal properties chi = 0");
    if (!heat || props == nullptr) {
      if (softens)
        throw InputError(material.where,
                         material_name(material) +
                             ": thermal softening (m, T0, Tm) and the failure strain's thermal "
                             "factor (d5) need a temperature field; give the material thermal "
                             "properties (" +
                             model.sources.words("thermal_properties") + ")");
      continue;
    }
    if (info.block < 0) continue;
    SolidBlock& block = blocks[static_cast<std::size_t>(info.block)];
    try {
      block.set_thermal({props->expansion, props->taylor_quinney > 0.0});
    } catch (const InputError& error) {
      throw InputError(material.where, error.what());
    }
    if (!block.plastic_work().empty()) {
      taylor_quinney[static_cast<std::size_t>(info.block)] = props->taylor_quinney;
      any = true;
    }
  }
  if (!any) taylor_quinney.clear();
}

// The Taylor-Quinney heat (Taylor & Quinney 1934, Proc. R. Soc. A 143:307): the share chi of
// each element's plastic work over the step becomes heat, 1/8 on each of its nodes, gathered as
// energy for the end of the mechanical step (advance_heat). Serial, in block and element order, so
// the sums do not depend on the number of threads.
void Simulation::Impl::gather_plastic_heat() {
  if (heat_energy.empty()) heat_energy.assign(n_nodes, 0.0);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const double chi = taylor_quinney[b];
    if (chi == 0.0) continue;
    const std::vector<double>& work = blocks[b].plastic_work();
    const std::vector<Hex8>& hexes = blocks[b].hexes();
    for (std::size_t e = 0; e < work.size(); ++e) {
      if (work[e] == 0.0) continue;
      const double share = 0.125 * chi * work[e];
      for (const std::int32_t node : hexes[e]) heat_energy[static_cast<std::size_t>(node)] += share;
    }
  }
}

}  // namespace abut
