static const char help[] = "Load control's depth search on monotone load-depth laws: converges within the tolerance\n"
                           "from loading and unloading states, with and without a slope, and finds a load out of "
                             "reach.\n";

#include "ind_forcesearch.h"
#include "unit_report.h"

typedef PetscReal (*Law)(PetscReal d);
static PetscReal Quadratic(PetscReal d) { return d > 0 ? 0.05 * d * d : 0; }        /* a sharp indenter */
static PetscReal Unload(PetscReal d) { return d > 20 ? 3.0 * PetscPowReal(d - 20, 1.5) : 0; } /* unloading, h_f 20 */
static PetscReal Hertz(PetscReal d) { return d > 0 ? 2.0 * PetscPowReal(d, 1.5) : 0; }
/* a slide at the accepted depth 30 (load 45 before it) raises or lowers the load by a tenth */
static PetscReal SlideHarder(PetscReal d) { return 1.1 * Quadratic(d); }
static PetscReal SlideSofter(PetscReal d) { return 0.9 * Quadratic(d); }

/* Runs a search to target from (d0, law(d0)), or with the load at d0 unknown (p0 < 0); returns the loads
   evaluated (-1: out of reach, -2: not in 60). */
static PetscInt SearchFrom(Law law, PetscReal target, PetscReal tol, PetscReal dmax, PetscReal d0, PetscReal p0,
                           PetscReal slope, PetscReal guess, PetscReal *dfound)
{
  IndForceSearch s;

  IndForceSearchStart(&s, target, tol, dmax, d0, p0);
  for (int k = 0; k < 60; ++k) {
    const PetscReal d    = IndForceSearchNext(&s, slope, guess);
    const int       done = IndForceSearchUpdate(&s, d, law(d));
    *dfound              = d;
    if (done == 1) return s.its;
    if (done == -1) return -1;
  }
  return -2;
}

static PetscInt Search(Law law, PetscReal target, PetscReal tol, PetscReal dmax, PetscReal d0, PetscReal slope,
                       PetscReal guess, PetscReal *dfound)
{
  return SearchFrom(law, target, tol, dmax, d0, law(d0), slope, guess, dfound);
}

int main(int argc, char **argv)
{
  PetscReal d, worst = 0;
  PetscInt  its, most = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  /* loading from rest, no slope known, a guess from depth control: targets along the curve */
  for (int k = 1; k <= 10; ++k) {
    const PetscReal target = 180.0 * k / 10;
    its = Search(Quadratic, target, 1e-10 * 180, 60, 0, 0, 6.0 * k, &d);
    worst = PetscMax(worst, its < 0 ? 1 : PetscAbsReal(Quadratic(d) - target) / 180);
    most  = PetscMax(most, its);
  }
  Report("quadratic loading from rest: |P - P*| / P_max", worst, 1e-10);
  Report("  loads evaluated per step, at most 12", (PetscReal)PetscMax(most - 12, 0), 0);
  /* the next step from an accepted state with the last step's slope */
  worst = 0, most = 0;
  for (int k = 1; k < 10; ++k) {
    const PetscReal d0 = 6.0 * k, target = Quadratic(6.0 * (k + 1)), slope = (Quadratic(d0) - Quadratic(d0 - 6)) / 6;
    its = Search(Quadratic, target, 1e-10 * 180, 60, d0, slope, 0, &d);
    worst = PetscMax(worst, its < 0 ? 1 : PetscAbsReal(Quadratic(d) - target) / 180);
    most  = PetscMax(most, its);
  }
  Report("quadratic, from the last step with its slope: |P - P*| / P_max", worst, 1e-10);
  Report("  loads evaluated per step, at most 10", (PetscReal)PetscMax(most - 10, 0), 0);
  /* Hertz */
  its = Search(Hertz, 100, 1e-12 * 100, 60, 10, 3 * PetscSqrtReal(10.0), 0, &d);
  Report("Hertz: the depth of P = 100", its < 0 ? 1 : PetscAbsReal(d - PetscPowReal(50, 2.0 / 3)), 1e-9);
  /* unloading from the top of a power-law branch to a fraction and to zero (where any depth above h_f will do) */
  {
    const PetscReal d0 = 50, p0 = Unload(d0), slope = 4.5 * PetscSqrtReal(30.0);
    its = Search(Unload, 0.3 * p0, 1e-10 * p0, 60, d0, slope, 0, &d);
    Report("unloading to 30%: |P - P*| / P_max", its < 0 ? 1 : PetscAbsReal(Unload(d) - 0.3 * p0) / p0, 1e-10);
    its = Search(Unload, 0, 1e-10 * p0, 60, d0, slope, 0, &d);
    Report("unloading to zero: the indenter has left (P = 0, depth <= h_f)", its < 0 || d > 20 ? 1 : Unload(d), 0);
  }
  /* a slide at constant load: the load at the accepted depth has changed, either way; the search
     starts there, not from the accepted load, and finds the depth sqrt(45 / 0.055) or sqrt(45 / 0.045) */
  its = SearchFrom(SlideHarder, 45, 1e-10 * 45, 60, 30, -1, 3, 0, &d);
  Report("slide that raises the load: the depth carrying the same load", its < 0 ? 1 : PetscAbsReal(d -
    PetscSqrtReal(45 / 0.055)), 1e-9);
  its = SearchFrom(SlideSofter, 45, 1e-10 * 45, 60, 30, -1, 3, 0, &d);
  Report("slide that lowers the load: the depth carrying the same load", its < 0 ? 1 : PetscAbsReal(d -
    PetscSqrtReal(45 / 0.045)), 1e-9);
  /* a load the block cannot carry within the largest depth */
  its = Search(Quadratic, 500, 1e-8, 60, 30, 3, 0, &d);
  Report("a load out of reach is reported at the largest depth", its == -1 && d == 60 ? 0 : 1, 0);
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
