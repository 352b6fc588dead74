#pragma once
// The temperature field of a model (issue 11): transient heat conduction in the hexahedra and
// shells (conduction in the mid-surface, shell4_thermal.hpp) of the parts whose material has
// thermal properties (ThermalModel), explicit in time (forward Euler with the lumped heat
// capacity), with prescribed temperatures, heat flux and convection on faces, and heat sources from
// the caller (plastic work, contact conduction and friction). Nodes outside the thermal parts keep
// their initial temperature.
//
// One step from T^n at time t to T^{n+1} at t + dt:
//   C_a (T_a^{n+1} - T_a^n) / dt = -(K T^n)_a + Q_a(t + dt/2, T^n) + S_a,
// K the conductance at the given (current) coordinates, Q the face loads (their curves at the
// middle of the step: exact over a step within one segment of a tabulated curve, whose breaks the
// caller steps onto, next_load_break), S the caller's sources [power]; then the prescribed nodes
// take T(t + dt). Stable while dt is below stable_step() (thermal_block.hpp), which the caller
// keeps by sub-cycling; a step whose change of temperature no stable step could make stops the
// run (InstabilityError).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "abut/contact/thermal_contact_element.hpp"
#include "abut/model/model.hpp"

namespace abut {

class StateArchive;

// Whether part `part_id` carries a temperature: its material has thermal properties (a thpid).
bool is_thermal_part(const Model& model, std::int64_t part_id);
// Per node, 1 when it carries a temperature: a node of a hexahedron or shell of a thermal part.
// The one definition of the thermal nodes, for the heat solver and for the deck's conditions.
std::vector<std::uint8_t> thermal_node_flags(const Model& model);
// InputError at the *CONTACT when a contact exchanges heat (ContactSpec::exchanges_heat) but a
// node of its surfaces carries no temperature.
void check_thermal_contacts(const Model& model);

// Heat balance since the start [energy]: stored = sum C (T - T0) over the thermal nodes; in =
// what the face loads, the prescribed temperatures and the caller's sources brought in.
struct HeatBalance {
  double stored = 0.0;
  double boundary = 0.0;    // face fluxes and convection
  double prescribed = 0.0;  // heat the prescribed temperatures put in (out: negative)
  double sources = 0.0;     // the caller's sources
  // The largest heat of the run so far: of the terms above and of the heat moved within the
  // model, sum C |T - T0| over the nodes (a closed exchange stores nothing on the whole).
  double largest = 0.0;
  double error() const { return stored - boundary - prescribed - sources; }
  // The error relative to the largest heat of the run (0 when no heat moved), never to a
  // difference near zero.
  double relative_error() const { return largest > 0.0 ? error() / largest : 0.0; }
};

class HeatSolver {
 public:
  // InputError (at the card) when a thermal load touches nodes outside the thermal parts, or a
  // material's thpid has no *PROP_THERMAL.
  explicit HeatSolver(const Model& model);
  ~HeatSolver();
  HeatSolver(HeatSolver&&) noexcept;
  HeatSolver& operator=(HeatSolver&&) noexcept;

  bool active() const;  // the model has thermal parts
  std::span<const double> temperature() const;
  std::span<const double> capacity() const;  // lumped heat capacity per node [energy/temperature]
  // The smallest element stable step at the coordinates of the last advance (or the reference).
  double stable_step() const;

  // One step of length dt from time t, at coordinates x, y, z (3 spans over the nodes), with the
  // caller's nodal heat sources [power] (may be empty): plan, flow over dt, hold at t + dt.
  void advance(double t, double dt, std::span<const double> x, std::span<const double> y,
               std::span<const double> z, std::span<const double> source);
  // The same step in parts, for a caller that spreads it over its own steps: plan the rates of
  // [t, t + span] at the current temperatures and coordinates, with the heat the caller exchanges
  // between nodes by conduction at these temperatures, e.g. through contact [power] (may be
  // empty; it sums to zero); InstabilityError when they would change a node by more than a
  // stable step can. Then let them flow over parts dt of the span into `nodes` (empty: every
  // node), holding the prescribed temperatures at times of its choice.
  void plan(double t, double span, std::span<const double> x, std::span<const double> y,
            std::span<const double> z, std::span<const double> exchange);
  void flow(double dt, std::span<const std::int32_t> nodes);
  // Heat the caller puts into the nodes `nodes` (empty: every node) at once, between steps:
  // power[i] * dt each
  // [energy] (the mechanics' heat of a mechanical step, or an exchange by conduction the caller
  // evaluates, e.g. through contact). Each node's temperature rises by its heat over its
  // capacity; a held node stays held (holding it takes the heat out). Booked as sources.
  void put_heat(std::span<const std::int32_t> nodes, std::span<const double> power, double dt);

  // Steady state at time t (issue 11, for static steps): K T = Q + S with the prescribed
  // temperatures held, face fluxes and convection at t, the caller's sources S [power] (may be
  // empty), at coordinates x, y, z, and the conduction through `contact` (thermal contact
  // points, thermal_contact_element.hpp); solved directly (CHOLMOD). Replaces the temperatures;
  // the heat balance is not advanced (nothing is stored in a steady state). InputError when no
  // temperature is held and no face convects (the temperature level is then undetermined).
  void solve_steady(double t, std::span<const double> x, std::span<const double> y,
                    std::span<const double> z, std::span<const double> source,
                    std::span<const ThermalContactElement> contact = {});

  // Sets the prescribed temperatures to their values at time t (for a caller whose mechanics
  // reads them more often than it plans steps), booking the heat they take in.
  void hold(double t);
  // The first break of a thermal load's tabulated curve after time t (infinity if none).
  double next_load_break(double t) const;

  const HeatBalance& balance() const;
  // Heat flowing into each node by conduction at the last advance [power] (for output).
  std::span<const double> conduction_rate() const;
  // Saves or loads the temperatures and the heat balance for a restart (state_archive.hpp).
  void archive(StateArchive& a);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace abut
