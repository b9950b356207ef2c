#pragma once
/* Oliver-Pharr analysis of a load-displacement curve (J. Mater. Res. 7 (1992) 1564; doc/theory.md
   section 3). Pure: no PETSc objects. Units: depth nm, load uN; H and moduli come out in GPa
   (1 uN/nm^2 = 1000 GPa). */
#include <petscsys.h>

typedef struct {
  PetscReal fraction;    /* fit the unloading points with P >= (1 - fraction) P_max; default 0.5 */
  PetscReal epsilon;     /* h_c = h_max - epsilon P_max / S; 0.75 */
  PetscReal beta;        /* E_r = sqrt(pi) / (2 beta) S / sqrt(A); 1.034 */
  PetscReal E_indenter;  /* GPa; 0 for a rigid indenter */
  PetscReal nu_indenter;
  PetscReal nu_sample;   /* for the sample's modulus from E_r */
} IndOPParams;

typedef struct {
  PetscReal P_max, h_max;    /* uN, nm */
  PetscReal alpha, h_f, m;   /* P = alpha (h - h_f)^m on the fitted branch */
  PetscInt  npoints;         /* fitted */
  PetscReal rms;             /* root-mean-square misfit of the fit, uN */
  PetscReal S;               /* contact stiffness dP/dh at h_max, uN/nm */
  PetscReal h_c, A;          /* contact depth nm, projected area nm^2 */
  PetscReal H, E_r, E;       /* hardness, reduced modulus, sample modulus; GPa */
} IndOPResult;

/* The area function A(h_c) in nm^2. */
typedef PetscReal (*IndAreaFn)(PetscReal h_c, void *ctx);

void IndOPParamsDefault(IndOPParams *p);
/* Analyses the curve (h[i], P[i]), i < n, in the order recorded: loading, then unloading after the
   largest load. Returns 0, or a positive code: 1 fewer than 3 points to fit, 2 the fit failed (not a
   power law with 0 < m), 3 a bad parameter, 4 the area function gives no area at h_c (h_c at or below the
   tip: r holds the fit, S, h_c and A, but no H, E_r or E). */
int IndOliverPharr(const PetscReal *h, const PetscReal *P, PetscInt n, const IndOPParams *p, IndAreaFn area,
  void *ctx, IndOPResult *r);
/* The same quantities from a known contact area A at P_max (e.g. the simulation's true area). E is
   NaN when E_r exceeds what the indenter's own compliance allows. */
void IndOPFromArea(const IndOPParams *p, const IndOPResult *fit, PetscReal A, PetscReal *H, PetscReal *E_r,
  PetscReal *E);
