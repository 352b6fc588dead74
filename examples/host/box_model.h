/* The host's own model in the host examples (examples/host/README.md): everything here is the
 * host's business, not abut's. Two boxes of 8 nodes, each node joined to the other 7 by a linear
 * spring (edges, face diagonals and body diagonals: a stiff, nearly rigid box), on a fixed square
 * plane, under gravity, with mass-proportional damping so that they come to rest. Box B stands on
 * the plane; box A starts above B, shifted sideways, and falls onto it. Units: m, kg, s, N.
 *
 * Nodes: box B 0-7, box A 8-15 (each: bottom 0-3 counter-clockwise seen from above, top 4-7),
 * plane 16-19. Explicit central differences: v(n+1/2) = v(n-1/2) + a(n) dt, x(n+1) = x(n) +
 * v(n+1/2) dt. */
#ifndef ABUT_EXAMPLE_BOX_MODEL_H
#define ABUT_EXAMPLE_BOX_MODEL_H

#include <math.h>
#include <stdint.h>
#include <string.h>

enum { BOX_NODES = 16, PLANE_NODES = 4, NODES = BOX_NODES + PLANE_NODES };

static const double kSide = 0.1;         /* box edge [m] */
static const double kNodeMass = 1.0;     /* [kg]: 8 kg per box */
static const double kPlaneMass = 1.0e6;  /* the fixed plane's nodes (their motion is held) */
static const double kSpring = 2.0e5;     /* each of a box's 28 springs [N/m] */
static const double kGravity = 9.81;     /* [m/s^2], along -z */
static const double kMassDamping = 10.0; /* [1/s]: f = -c m v on every box node */
static const double kPenalty = 1.0e8;    /* contact penalty pfac [N/m^3] */

typedef struct {
  double x[NODES], y[NODES], z[NODES];
  double vx[NODES], vy[NODES], vz[NODES];
  double fx[NODES], fy[NODES], fz[NODES];
  double mass[NODES];
  double rest[2][8][8]; /* spring rest lengths */
  double damping_work;  /* work of the mass-proportional damping so far */
  double gravity_work;  /* work of gravity so far */
} BoxModel;

/* The outward facets of a box whose first node is `first` (4 node indices each). */
static inline void box_facets(int32_t first, int32_t facets[24]) {
  static const int32_t local[24] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4,
                                    1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
  for (int i = 0; i < 24; ++i) facets[i] = first + local[i];
}

/* The plane: one square facet, its normal up. */
static inline void plane_facet(int32_t facets[4]) {
  for (int i = 0; i < 4; ++i) facets[i] = BOX_NODES + i;
}

static inline void place_box(BoxModel* m, int first, double x0, double y0, double z0) {
  for (int a = 0; a < 8; ++a) {
    const int corner = a % 4;
    m->x[first + a] = x0 + ((corner == 1 || corner == 2) ? kSide : 0.0);
    m->y[first + a] = y0 + ((corner >= 2) ? kSide : 0.0);
    m->z[first + a] = z0 + (a >= 4 ? kSide : 0.0);
  }
}

static inline void box_model_init(BoxModel* m) {
  memset(m, 0, sizeof *m);
  place_box(m, 0, -0.05, -0.05, 0.0);    /* B on the plane */
  place_box(m, 8, -0.045, -0.047, 0.13); /* A 30 mm above B, shifted 5 mm and 3 mm */
  const double corner[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  for (int i = 0; i < PLANE_NODES; ++i) {
    m->x[BOX_NODES + i] = corner[i][0];
    m->y[BOX_NODES + i] = corner[i][1];
  }
  for (int n = 0; n < NODES; ++n) m->mass[n] = n < BOX_NODES ? kNodeMass : kPlaneMass;
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) {
        const int p = 8 * b + i, q = 8 * b + j;
        m->rest[b][i][j] = sqrt((m->x[p] - m->x[q]) * (m->x[p] - m->x[q]) +
                                (m->y[p] - m->y[q]) * (m->y[p] - m->y[q]) +
                                (m->z[p] - m->z[q]) * (m->z[p] - m->z[q]));
      }
}

/* The host's internal and external forces on the boxes (the plane is held), into f. */
static inline void box_model_forces(BoxModel* m) {
  memset(m->fx, 0, sizeof m->fx);
  memset(m->fy, 0, sizeof m->fy);
  memset(m->fz, 0, sizeof m->fz);
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < 8; ++i)
      for (int j = i + 1; j < 8; ++j) {
        const int p = 8 * b + i, q = 8 * b + j;
        const double dx = m->x[q] - m->x[p], dy = m->y[q] - m->y[p], dz = m->z[q] - m->z[p];
        const double length = sqrt(dx * dx + dy * dy + dz * dz);
        const double t = kSpring * (length - m->rest[b][i][j]) / length;
        m->fx[p] += t * dx, m->fy[p] += t * dy, m->fz[p] += t * dz;
        m->fx[q] -= t * dx, m->fy[q] -= t * dy, m->fz[q] -= t * dz;
      }
  for (int n = 0; n < BOX_NODES; ++n) {
    m->fz[n] -= m->mass[n] * kGravity;
    m->fx[n] -= kMassDamping * m->mass[n] * m->vx[n];
    m->fy[n] -= kMassDamping * m->mass[n] * m->vy[n];
    m->fz[n] -= kMassDamping * m->mass[n] * m->vz[n];
  }
}

/* One step of central differences with the forces in f (the host's and the contact's); books the
 * work of gravity and damping over it (damping at the mean velocity of the two half steps). */
static inline void box_model_step(BoxModel* m, double dt) {
  for (int n = 0; n < BOX_NODES; ++n) {
    const double wx = m->vx[n], wy = m->vy[n], wz = m->vz[n];
    m->vx[n] += m->fx[n] / m->mass[n] * dt;
    m->vy[n] += m->fy[n] / m->mass[n] * dt;
    m->vz[n] += m->fz[n] / m->mass[n] * dt;
    const double mx = 0.5 * (wx + m->vx[n]), my = 0.5 * (wy + m->vy[n]), mz = 0.5 * (wz + m->vz[n]);
    m->damping_work += kMassDamping * m->mass[n] * (mx * mx + my * my + mz * mz) * dt;
    m->gravity_work += m->mass[n] * kGravity * m->vz[n] * -dt;
    m->x[n] += m->vx[n] * dt;
    m->y[n] += m->vy[n] * dt;
    m->z[n] += m->vz[n] * dt;
  }
}

/* Kinetic energy (half-step velocities) and the springs' energy of the boxes. */
static inline double box_model_energy(const BoxModel* m) {
  double e = 0.0;
  for (int n = 0; n < BOX_NODES; ++n)
    e += 0.5 * m->mass[n] * (m->vx[n] * m->vx[n] + m->vy[n] * m->vy[n] + m->vz[n] * m->vz[n]);
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < 8; ++i)
      for (int j = i + 1; j < 8; ++j) {
        const int p = 8 * b + i, q = 8 * b + j;
        const double dx = m->x[q] - m->x[p], dy = m->y[q] - m->y[p], dz = m->z[q] - m->z[p];
        const double s = sqrt(dx * dx + dy * dy + dz * dz) - m->rest[b][i][j];
        e += 0.5 * kSpring * s * s;
      }
  return e;
}

/* The stable step of the host's springs: 2 / omega_max with omega_max^2 at most twice a node's
 * 7 springs over its mass (Gershgorin), less a margin. */
static inline double box_model_stable_step(void) {
  return 0.5 * 2.0 / sqrt(2.0 * 7.0 * kSpring / kNodeMass);
}

#endif /* ABUT_EXAMPLE_BOX_MODEL_H */
