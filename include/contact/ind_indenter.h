#pragma once
/* Rigid analytic indenters (doc/theory.md section 2). Pure: no PETSc objects, no globals.

   The axis is vertical through (axis[0], axis[1]); the indenter comes down from above onto a body
   whose undeformed top surface is the plane z = surface. `depth` is how far its lowest point has
   gone below that plane (depth 0 touches it). Every shape except the flat punch is the set of points
   within `tip_radius` of a sharp core (a point, a cone, a pyramid) whose apex sits tip_radius above
   the lowest point: the sphere is a point core, and pyramids come out with edges and tip rounded to
   that radius, as real tips are. The signed gap is then (distance to the core) - tip_radius, and its
   gradient, the unit normal, points from the indenter into the body. */
#include <petscsys.h>

#ifndef PETSC_SUCCESS
  #define PETSC_SUCCESS 0 /* PETSc < 3.19 returns plain 0 */
#endif

typedef enum {
  IND_INDENTER_SPHERE,
  IND_INDENTER_CONE,
  IND_INDENTER_BERKOVICH,   /* modified Berkovich: 3 faces at 65.27 deg to the axis */
  IND_INDENTER_VICKERS,     /* 4 faces at 68 deg */
  IND_INDENTER_CUBE_CORNER, /* 3 faces at 35.26 deg */
  IND_INDENTER_FLAT,        /* flat cylindrical punch of radius `radius` */
  IND_INDENTER_TABLE        /* of revolution, its height above the lowest point given as a table of the radius */
} IndIndenterType;
/* Names for PetscOptionsEnum(). */
extern const char *const IndIndenterTypes[];

#define IND_INDENTER_MAX_FACES 4

typedef struct {
  IndIndenterType type;
  PetscReal       radius;   /* sphere or tip radius (nm), 0 for sharp; punch radius */
  /* The gap of a sharp (radius 0) cone or pyramid is that of the shape rounded by this (nm; 0: exactly
     sharp). Inside a sharp core the nearest face jumps across its edges and apex, so a node pressed
     onto the apex has no position where its single normal balances it and Newton flips it from face
     to face; rounded, the normal turns continuously. The area function stays the sharp one. */
  PetscReal       rounding;
  PetscReal       angle;    /* cone half-angle or pyramid face-to-axis angle, radians */
  PetscReal       rotation; /* pyramids: azimuth of the first face's outward normal, radians */
  PetscReal       axis[2];  /* x, y of the axis, nm */
  PetscReal       surface;  /* z of the undeformed top surface, nm */
  PetscReal       depth;    /* depth of the lowest point below `surface`, nm */
  /* The table's nprofile points (r, height), nm, r from 0 increasing, height from 0 not decreasing (borrowed);
     straight between them and past the last point along the last segment, which must rise. */
  const PetscReal *profile;
  PetscInt         nprofile;
  /* Derived by IndIndenterSetUp: */
  PetscInt  nfaces;
  PetscReal m[IND_INDENTER_MAX_FACES][3]; /* outward unit normals of the core pyramid's faces */
} IndIndenter;

/* Fills the face angle and count of the pyramid types (when angle is 0, the standard one) and the
   face normals. Returns 0, or 1 if a parameter is out of range (the caller names the option), or a
   table's points are not as IndIndenter says. */
int IndIndenterSetUp(IndIndenter *ind);

/* Oliver and Pharr's constants for the shape: epsilon of h_c = h_max - epsilon P_max / S (0.72 for a cone, 1 for a
   flat punch, 0.75 for the paraboloid that a sphere, a table and a pyramid's unloading resemble) and beta of
   E_r = sqrt(pi) / (2 beta) S / sqrt(A) (1 for shapes of revolution, 1.034 for the three-sided pyramids and 1.012
   for the four-sided one: King, Int. J. Solids Struct. 23 (1987) 1657; Oliver and Pharr, J. Mater. Res. 19 (2004)
   3). */
void IndIndenterOPConstants(IndIndenterType type, PetscReal *epsilon, PetscReal *beta);

/* Signed gap (nm, positive open) of the point x and the unit normal n (gradient of the gap). */
void IndIndenterGap(const IndIndenter *ind, const PetscReal x[3], PetscReal *gap, PetscReal n[3]);

/* An orthonormal tangent basis of the plane normal to n, a smooth function of n away from n = +-y. */
void IndIndenterTangents(const PetscReal n[3], PetscReal t1[3], PetscReal t2[3]);

/* Projected (horizontal) area of the indenter's cross-section at height hc above its lowest point:
   the area function A(h_c) of Oliver and Pharr, nm^2. Closed forms for the sphere, the punch, cones
   and sharp pyramids; for rounded pyramids the section's boundary is found along rays and
   integrated, to about 1e-12 relative. */
PetscReal IndIndenterArea(const IndIndenter *ind, PetscReal hc);

/* Radius (nm) of the circle where the indenter at depth h (nm) meets the undeformed surface, the edge a
   contact without pile-up or sink-in would have; for a pyramid that of the cone of equal cross-section
   areas and tip radius. A flat punch's is its radius at every depth. */
PetscReal IndIndenterEdgeRadius(const IndIndenter *ind, PetscReal h);
/* Its inverse: the depth at which that edge reaches radius r (PETSC_MAX_REAL: never, as for a sphere's
   radius or a flat punch). */
PetscReal IndIndenterEdgeDepth(const IndIndenter *ind, PetscReal r);
