// The C interface (abut/abut_contact.h) over ContactInterface: handles that own C++ objects, and
// every exception turned into a status and a message for abut_last_error().
#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "abut/abut_contact.h"
#include "abut/contact/interface.hpp"
#include "abut/contact/settings_by_name.hpp"

struct abut_contact_settings {
  abut::ContactSettings settings;
};
struct abut_surface {
  abut::ContactSurface surface;
};
struct abut_contact {
  abut::ContactInterface interface;
  std::size_t node_count = 0;
};

namespace {

thread_local std::string last_error;
thread_local std::string last_setting;

int fail(const std::string& setting, const std::string& message) {
  last_setting = setting;
  last_error = message;
  return ABUT_ERROR;
}

// Runs `call` and turns an exception into ABUT_ERROR with its message.
int guarded(const std::function<void()>& call) {
  try {
    call();
    return ABUT_OK;
  } catch (const abut::ContactSetupError& e) {
    return fail(e.setting(), e.what());
  } catch (const std::exception& e) {
    return fail("", e.what());
  } catch (...) {
    return fail("", "unknown error");
  }
}

// Facets of `count` x 4 node indices, checked as they arrive (the interface checks them against
// the node count).
int add_facets(abut_surface* surface, std::size_t count, const std::int32_t* nodes,
               std::int64_t part, double penalty, double thickness, bool shell) {
  if (!surface) return fail("surface", "abut_surface_add: no surface (NULL)");
  if (count > 0 && !nodes) return fail("surface", "abut_surface_add: no node array (NULL)");
  if (!(penalty > 0.0) || !std::isfinite(penalty))
    return fail("surface", "abut_surface_add: the penalty must be positive and finite");
  if (!(thickness > 0.0) || !std::isfinite(thickness))
    return fail("surface", "abut_surface_add: the thickness must be positive and finite");
  for (std::size_t f = 0; f < count; ++f) {
    std::array<std::int32_t, 4> n{};
    std::copy_n(nodes + 4 * f, 4, n.begin());
    if (shell)
      surface->surface.add_shell(n, part, penalty, thickness);
    else
      surface->surface.add(n, part, penalty, thickness);
  }
  return ABUT_OK;
}

}  // namespace

extern "C" {

const char* abut_last_error(void) { return last_error.c_str(); }
const char* abut_last_error_setting(void) { return last_setting.c_str(); }

abut_contact_settings* abut_contact_settings_create(void) { return new abut_contact_settings; }

int abut_contact_settings_set(abut_contact_settings* settings, const char* name, double value) {
  if (!settings || !name) return fail("", "abut_contact_settings_set: no settings or name (NULL)");
  return guarded([&] { abut::set_by_name(settings->settings, name, value); });
}

void abut_contact_settings_destroy(abut_contact_settings* settings) { delete settings; }

abut_surface* abut_surface_create(void) { return new abut_surface; }

int abut_surface_add_facets(abut_surface* surface, size_t count, const int32_t* nodes, int64_t part,
                            double penalty, double thickness) {
  return add_facets(surface, count, nodes, part, penalty, thickness, false);
}

int abut_surface_add_shells(abut_surface* surface, size_t count, const int32_t* nodes, int64_t part,
                            double penalty, double thickness) {
  return add_facets(surface, count, nodes, part, penalty, thickness, true);
}

size_t abut_surface_facet_count(const abut_surface* surface) {
  return surface ? surface->surface.size() : 0;
}

void abut_surface_destroy(abut_surface* surface) { delete surface; }

abut_contact* abut_contact_create(const abut_contact_settings* settings,
                                  const abut_surface* surface1, const abut_surface* surface2,
                                  size_t node_count, const double* node_mass, const double* x,
                                  const double* y, const double* z, size_t secondary_count,
                                  const int32_t* secondary_nodes) {
  if (!settings || !surface1 || !surface2) {
    fail("", "abut_contact_create: settings and both surfaces are needed (NULL given)");
    return nullptr;
  }
  if (node_count > 0 && (!node_mass || !x || !y || !z)) {
    fail("", "abut_contact_create: masses and coordinates are needed (NULL given)");
    return nullptr;
  }
  if (secondary_count > 0 && !secondary_nodes) {
    fail("", "abut_contact_create: secondary_count > 0 with no node array (NULL)");
    return nullptr;
  }
  abut_contact* made = nullptr;
  guarded([&] {
    abut::ContactInput initial;
    initial.x = {x, node_count};
    initial.y = {y, node_count};
    initial.z = {z, node_count};
    made = new abut_contact{abut::ContactInterface(settings->settings, surface1->surface,
                                                   surface2->surface, {node_mass, node_count},
                                                   initial, {secondary_nodes, secondary_count}),
                            node_count};
  });
  return made;
}

void abut_contact_destroy(abut_contact* contact) { delete contact; }

int abut_contact_apply(abut_contact* contact, double time, double dt, const double* x,
                       const double* y, const double* z, const double* vx, const double* vy,
                       const double* vz, double* fx, double* fy, double* fz) {
  if (!contact) return fail("", "abut_contact_apply: no contact (NULL)");
  const std::size_t n = contact->node_count;
  if (n > 0 && (!x || !y || !z || !vx || !vy || !vz || !fx || !fy || !fz))
    return fail("", "abut_contact_apply: coordinates, velocities and forces are needed (NULL)");
  return guarded([&] {
    abut::ContactInput in;
    in.x = {x, n};
    in.y = {y, n};
    in.z = {z, n};
    in.vx = {vx, n};
    in.vy = {vy, n};
    in.vz = {vz, n};
    in.time = time;
    in.dt = dt;
    abut::ContactForces out{{fx, n}, {fy, n}, {fz, n}, {}, {}};
    contact->interface.apply(in, out);
  });
}

double abut_contact_stable_step(const abut_contact* contact) {
  if (!contact) return std::numeric_limits<double>::quiet_NaN();
  return contact->interface.stats().step_bound();
}

int abut_contact_get_stats(const abut_contact* contact, abut_contact_stats* stats) {
  if (!contact || !stats) return fail("", "abut_contact_get_stats: NULL argument");
  const abut::ContactStats& s = contact->interface.stats();
  *stats = abut_contact_stats{{s.force.x, s.force.y, s.force.z},
                              s.normal_force,
                              s.tangential_force,
                              s.elastic_energy,
                              s.damping_energy,
                              s.friction_energy,
                              s.released_energy,
                              s.max_penetration,
                              static_cast<double>(s.active_points)};
  return ABUT_OK;
}

size_t abut_contact_save(const abut_contact* contact, char* buffer, size_t capacity) {
  if (!contact) return 0;
  std::size_t size = 0;
  guarded([&] {
    const std::vector<char> bytes = contact->interface.save_state();
    size = bytes.size();
    if (buffer && capacity >= size) std::memcpy(buffer, bytes.data(), size);
  });
  return size;
}

int abut_contact_restore(abut_contact* contact, const char* buffer, size_t size) {
  if (!contact || (size > 0 && !buffer)) return fail("", "abut_contact_restore: NULL argument");
  return guarded(
      [&] { contact->interface.restore_state(std::vector<char>(buffer, buffer + size)); });
}

}  // extern "C"
