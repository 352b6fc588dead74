/* abut's contact library for C hosts (and Fortran through iso_c_binding): penalty contact between
 * two surfaces of a host's mesh, one explicit step at a time. The host owns its nodal arrays; the
 * library reads coordinates and velocities and adds forces. Units are the host's own (consistent:
 * e.g. mm, s, t, N, MPa).
 *
 *   abut_contact_settings* s = abut_contact_settings_create();
 *   abut_contact_settings_set(s, "friction", 0.3);
 *   abut_surface* a = abut_surface_create();  (and b)
 *   abut_surface_add_facets(a, n, nodes, part, penalty, thickness);
 *   abut_contact* c = abut_contact_create(s, a, b, node_count, mass, x, y, z, 0, NULL);
 *   each step: abut_contact_apply(c, t, dt, x, y, z, vx, vy, vz, fx, fy, fz);
 *              dt_next <= abut_contact_stable_step(c)
 *   abut_contact_destroy(c); abut_surface_destroy(a); abut_contact_settings_destroy(s);
 *
 * Every function that can fail returns ABUT_OK (0) or ABUT_ERROR, or NULL for a handle, and
 * abut_last_error() then says why. Node indices are 0-based. The C++ interface this wraps is
 * abut/contact/interface.hpp (docs/contact.md). */
#ifndef ABUT_CONTACT_H
#define ABUT_CONTACT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { ABUT_OK = 0, ABUT_ERROR = 1 };

typedef struct abut_contact_settings abut_contact_settings;
typedef struct abut_surface abut_surface;
typedef struct abut_contact abut_contact;

/* The message of the last call that failed in this thread ("" if none), and the setting it names
 * ("surface1", "friction", ...; "" when it names none). Valid until the next failing call. */
const char* abut_last_error(void);
const char* abut_last_error_setting(void);

/* Settings, with the library's defaults (seed 000, IMPETUS *CONTACT: symmetric surface to surface,
 * 2 x 2 points per facet, frictionless, 10% of critical damping). abut_contact_settings_set takes
 * one of these names (a flag is 0 or 1):
 *   node_to_surface   flag: the nodes of surface 1 are the contact points (else integration
 *                     points on the facets of both surfaces)
 *   one_way           flag: only surface 1's points act (else both surfaces', half weight each)
 *   accuracy_level    points per facet (surface to surface): 1 centre, 2: 2 x 2, 3: 3 x 3
 *   friction          Coulomb coefficient, static and sliding (0: frictionless)
 *   friction_static, friction_sliding   the two apart (static >= sliding)
 *   damping           fraction of critical damping of each contact spring
 *   detection_depth   [length] how deep a point is still found (default: half the element
 *                     thickness)
 *   search_margin     [length] broad-phase margin (default: half the smallest detection depth)
 *   begin_time, end_time   the contact's time window
 *   initial_offset    [length] initial penetration subtracted until separation
 *   initial_max       [length] deeper initial penetrations are released (default 4% of the
 *                     element thickness)
 *   edge_angle        [degrees] facets turned further meet at a sharp edge (default 20)
 *   tangential_penalty  [stress / length] tangential spring (default: the normal penalty)
 *   stick_stress      [stress] points tie on touch and hold up to this traction */
abut_contact_settings* abut_contact_settings_create(void);
int abut_contact_settings_set(abut_contact_settings* settings, const char* name, double value);
void abut_contact_settings_destroy(abut_contact_settings* settings);

/* A contact surface: facets of 4 node indices each, counter-clockwise seen from outside the body
 * (a triangle repeats its last node), with the part id, penalty stiffness pfac [stress / length]
 * and element thickness along the facet's normal [length] of all `count` facets added. Shells:
 * each facet is a shell's mid-surface of that thickness, touched on both sides. */
abut_surface* abut_surface_create(void);
int abut_surface_add_facets(abut_surface* surface, size_t count, const int32_t* nodes, int64_t part,
                            double penalty, double thickness);
int abut_surface_add_shells(abut_surface* surface, size_t count, const int32_t* nodes, int64_t part,
                            double penalty, double thickness);
size_t abut_surface_facet_count(const abut_surface* surface);
void abut_surface_destroy(abut_surface* surface);

/* The interface between surface1 and surface2 (the same surface: self contact) of a mesh of
 * node_count nodes with these masses and initial coordinates (which fix sharp edges, areas and
 * initial penetrations). Node to surface: secondary_nodes (secondary_count of them; 0 and NULL:
 * every node of surface 1) are the contact points. The settings and surfaces are copied. */
abut_contact* abut_contact_create(const abut_contact_settings* settings,
                                  const abut_surface* surface1, const abut_surface* surface2,
                                  size_t node_count, const double* node_mass, const double* x,
                                  const double* y, const double* z, size_t secondary_count,
                                  const int32_t* secondary_nodes);
void abut_contact_destroy(abut_contact* contact);

/* One step: adds the contact forces of the state (x, v) at `time` to fx, fy, fz (node_count
 * each); dt is the step over which friction and damping work are integrated. */
int abut_contact_apply(abut_contact* contact, double time, double dt, const double* x,
                       const double* y, const double* z, const double* vx, const double* vy,
                       const double* vz, double* fx, double* fy, double* fz);

/* The largest step the contact allows next: the least of its springs' stable step, the step
 * before open points may touch and the step that keeps the penalty's kink small (interface.hpp,
 * ContactStats). Infinite when nothing bounds it. */
double abut_contact_stable_step(const abut_contact* contact);

typedef struct abut_contact_stats {
  double force[3];         /* total contact force on the nodes of surface 1 */
  double normal_force;     /* sum of the normal forces of the active points */
  double tangential_force; /* sum of the magnitudes of their tangential forces */
  double elastic_energy;   /* in the penalty springs now */
  double damping_energy;   /* done by the contact damping so far */
  double friction_energy;  /* dissipated by friction so far */
  double released_energy;  /* spring energy that vanished without work so far */
  double max_penetration;  /* largest penetration beyond the initial offsets */
  double active_points;    /* points in contact (a count) */
} abut_contact_stats;
int abut_contact_get_stats(const abut_contact* contact, abut_contact_stats* stats);

/* The evolving state (points, friction and tie history, statistics) as bytes, for a restart:
 * abut_contact_save returns the size and writes it to `buffer` when `capacity` suffices (call it
 * with NULL, 0 first); abut_contact_restore loads it into an interface made from the same model. */
size_t abut_contact_save(const abut_contact* contact, char* buffer, size_t capacity);
int abut_contact_restore(abut_contact* contact, const char* buffer, size_t size);

#ifdef __cplusplus
}
#endif

#endif /* ABUT_CONTACT_H */
