/* A C host of abut's contact library (abut/abut_contact.h): box A falls onto box B, which stands
 * on a fixed plane (box_model.h is the host's own model). Two contact interfaces: A against B
 * (surface to surface, symmetric, Coulomb friction 0.3) and both boxes against the plane (node to
 * surface, the boxes' nodes on the plane). Prints a history line every 0.25 s and, at rest, the
 * contact forces against the weights they carry (examples/host/README.md). */
#include <abut/abut_contact.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "box_model.h"

static void check(int status) {
  if (status != ABUT_OK) {
    fprintf(stderr, "abut: %s (setting: %s)\n", abut_last_error(), abut_last_error_setting());
    exit(1);
  }
}

static abut_surface* box_surface(int32_t first) {
  int32_t facets[24];
  box_facets(first, facets);
  abut_surface* s = abut_surface_create();
  check(abut_surface_add_facets(s, 6, facets, first == 0 ? 1 : 2, kPenalty, kSide));
  return s;
}

int main(void) {
  static BoxModel m;
  box_model_init(&m);

  abut_surface* a = box_surface(8);
  abut_surface* b = box_surface(0);
  abut_surface* boxes = abut_surface_create();
  int32_t facets[24];
  for (int32_t first = 0; first <= 8; first += 8) {
    box_facets(first, facets);
    check(abut_surface_add_facets(boxes, 6, facets, first == 0 ? 1 : 2, kPenalty, kSide));
  }
  abut_surface* plane = abut_surface_create();
  plane_facet(facets);
  check(abut_surface_add_facets(plane, 1, facets, 3, kPenalty, kSide));

  abut_contact_settings* s = abut_contact_settings_create();
  check(abut_contact_settings_set(s, "friction", 0.3));
  abut_contact* ab = abut_contact_create(s, a, b, NODES, m.mass, m.x, m.y, m.z, 0, NULL);
  check(abut_contact_settings_set(s, "friction", 0.0));
  check(abut_contact_settings_set(s, "node_to_surface", 1));
  check(abut_contact_settings_set(s, "one_way", 1));
  abut_contact* ground =
      abut_contact_create(s, boxes, plane, NODES, m.mass, m.x, m.y, m.z, 0, NULL);
  if (!ab || !ground) check(ABUT_ERROR);

  const double end = 4.0, every = 0.25;
  double t = 0.0, dt = box_model_stable_step(), next = 0.0, worst = 0.0;
  abut_contact_stats sab, sground;
  printf("%8s %12s %12s %12s %12s\n", "t [s]", "z_A [m]", "N_AB [N]", "N_floor [N]", "balance");
  for (;;) {
    box_model_forces(&m);
    check(abut_contact_apply(ab, t, dt, m.x, m.y, m.z, m.vx, m.vy, m.vz, m.fx, m.fy, m.fz));
    check(abut_contact_apply(ground, t, dt, m.x, m.y, m.z, m.vx, m.vy, m.vz, m.fx, m.fy, m.fz));
    check(abut_contact_get_stats(ab, &sab));
    check(abut_contact_get_stats(ground, &sground));
    if (t >= next - 1e-12) {
      /* Energy balance: what the boxes hold plus what the contacts hold or took, against the
       * work of gravity (the boxes start at rest with relaxed springs). */
      double held = box_model_energy(&m) + m.damping_work;
      const abut_contact_stats* both[2] = {&sab, &sground};
      for (int i = 0; i < 2; ++i)
        held += both[i]->elastic_energy + both[i]->damping_energy + both[i]->friction_energy +
                both[i]->released_energy;
      const double balance = (held - m.gravity_work) / fmax(m.gravity_work, 1e-30);
      if (fabs(balance) > worst) worst = fabs(balance);
      double za = 0.0;
      for (int n = 8; n < 16; ++n) za += m.z[n] / 8.0;
      printf("%8.3f %12.8f %12.6f %12.6f %12.3e\n", t, za, sab.normal_force, sground.normal_force,
             balance);
      next += every;
    }
    if (t >= end) break;
    box_model_step(&m, dt);
    t += dt;
    const double bound = fmin(abut_contact_stable_step(ab), abut_contact_stable_step(ground));
    dt = fmin(box_model_stable_step(), 0.9 * bound);
  }
  const double g = kGravity * kNodeMass * 8.0;
  printf("at rest: N_AB / (m_A g) = %.9f, N_floor / ((m_A + m_B) g) = %.9f, worst balance %.3e\n",
         sab.normal_force / g, sground.normal_force / (2.0 * g), worst);

  abut_contact_destroy(ab);
  abut_contact_destroy(ground);
  abut_contact_settings_destroy(s);
  abut_surface_destroy(a);
  abut_surface_destroy(b);
  abut_surface_destroy(boxes);
  abut_surface_destroy(plane);
  return 0;
}
