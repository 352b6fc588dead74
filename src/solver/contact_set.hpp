#pragma once
// The *CONTACT definitions of a model turned into contact-library interfaces: surfaces from
// parts, part sets or all exterior faces; penalties per part (given or automatic, seed 000);
// friction and wear functions and gid regions as callbacks into the model.
#include <cstdint>
#include <span>
#include <vector>

#include "abut/contact/interface.hpp"
#include "abut/contact/removed_nodes.hpp"
#include "abut/contact/tool_contact.hpp"
#include "abut/mesh/skin.hpp"
#include "abut/model/model.hpp"
#include "abut/solver/contact_report.hpp"
#include "tool_motion.hpp"

namespace abut {

// Surface 1 of a contact or tie: its faces, and for a node set (node-to-surface) its nodes, the
// faces being the contact faces (exterior faces of hexes, shells) that hold at least one of them
// (InputError at the set if a node is on none). `exposed_faces`: as contact_faces.
struct SecondarySurface {
  std::vector<std::int32_t> nodes;  // empty unless surface 1 is a node set
  std::vector<SkinFace> faces;
};
SecondarySurface secondary_surface(const Model& model, const EntityRef& surface1, bool merge,
                                   bool exposed_faces);

class ContactSet {
 public:
  // `node_mass`: lumped nodal masses; initial velocities give v_max of the automatic penalty;
  // `tied_nodes`: the exact ties' nodes, which contacts with tied_nodes REMOVE drop.
  ContactSet(const Model& model, std::span<const double> node_mass, std::span<const double> vx0,
             std::span<const double> vy0, std::span<const double> vz0,
             const RemovedNodes& tied_nodes = {});

  bool empty() const { return slots_.empty(); }
  // Adds every interface's forces for the state `in`; also keeps them per node for output.
  void apply(const ContactInput& in, std::span<double> fx, std::span<double> fy,
             std::span<double> fz);
  // Switches contact c (index in model.contacts) on or off for the next apply(): the solver's
  // sensors (*CONTACT_SENSOR), decided before every apply.
  void set_enabled(std::size_t c, bool on) {
    if (slots_[c].tool)
      tools_[slots_[c].index].set_enabled(on);
    else
      interfaces_[slots_[c].index].set_enabled(on);
  }
  // touched[node] = 1 for the nodes of contact c's surface 1 in contact after the last apply()
  // (ContactInterface::mark_secondary_nodes_in_contact; *CONTACT_RELEASE_BC).
  void mark_secondary_nodes_in_contact(std::size_t c, std::span<std::uint8_t> touched) const {
    if (slots_[c].tool)
      tools_[slots_[c].index].mark_secondary_nodes_in_contact(touched);
    else
      interfaces_[slots_[c].index].mark_secondary_nodes_in_contact(touched);
  }
  // Smallest stable step of the contact springs and the interface that sets it (-1: none), with
  // the kink's bound (ContactStats::kink_step); `springs`: the smallest without it.
  double stable_step(std::int64_t* limiting_contact, double* springs = nullptr) const;
  // Element erosion (ContactInterface::erode): `eroded` per element, hexes then shells.
  void erode(std::span<const std::uint8_t> eroded);
  double elastic_and_damping_energy() const;  // "contact" column of energy.csv
  double friction_energy() const;
  double released_energy() const;  // ContactStats::released_energy, summed
  double tool_work() const;        // ContactStats::tool_work, summed: external work of the tools
  // Thermal contact (*CONTACT fid_thermal, fric_heat, *CONTACT_THERMAL): the heat into each node
  // [power] (friction, and conduction when apply() had temperatures) and each node's conductance
  // through contact [power/temperature] of the last apply(); empty without thermal contact.
  bool thermal() const { return thermal_; }
  std::span<const double> heat() const { return heat_; }
  std::span<const double> conductance() const { return conductance_; }
  // For a caller that steps its heat on its own clock (ContactInterface::conduct_heat; apply()
  // then gets no temperatures): the heat conducted into each node at `temperature` through the
  // partners of the last apply(), added to `heat` [power]; the reports show that flow, booked
  // over the time it flows by book_conducted_heat.
  void conduct_heat(std::span<const double> temperature, std::span<double> heat);
  void book_conducted_heat(double duration);
  // Every node of the contacts' surfaces, sorted: the only nodes apply() and conduct_heat() load.
  std::span<const std::int32_t> surface_nodes() const { return surface_nodes_; }

  // Penalties and the statistics of the last apply(), one per interface.
  const std::vector<ContactReport>& reports() const { return reports_; }
  // Nodal output fields summed over all interfaces (force interleaved x, y, z).
  void nodal_fields(std::vector<double>& force, std::vector<double>& pressure,
                    std::vector<double>& wear) const;
  // Saves or loads every interface's state and the last step's nodal fields (restart).
  void archive(StateArchive& a);

 private:
  // A *CONTACT whose surface 2 is an analytic tool (*CONTACT_TOOL): surface 1's faces and nodes
  // as the meshed contacts take them, pfac of surface 1's own parts.
  void add_tool_contact(const ContactSpec& spec, const std::vector<SkinFace>& faces1,
                        const std::vector<std::int32_t>& secondary_nodes,
                        std::span<const double> node_mass, const ContactInput& initial,
                        double v_max);

  const Model& model_;
  std::vector<ContactReport> reports_;
  // Contact c of the model is interfaces_[slots_[c].index] (two meshed surfaces) or, with an
  // analytic tool as surface 2 (*CONTACT_TOOL), tools_[slots_[c].index] moved by motions_.
  struct Slot {
    bool tool = false;
    std::size_t index = 0;
  };
  std::vector<Slot> slots_;
  std::vector<ContactInterface> interfaces_;
  std::vector<ToolContact> tools_;
  std::vector<ToolMotion> motions_;
  std::vector<double> cfx_, cfy_, cfz_;  // contact force per node, last step
  // The nodes any interface can load (their surfaces' nodes, sorted): the only entries of the
  // per-node arrays that apply() clears and adds, instead of every node of the model.
  std::vector<std::int32_t> surface_nodes_;
  bool thermal_ = false;
  std::vector<double> heat_, conductance_;  // per node, last step (thermal contact only)
};

}  // namespace abut
