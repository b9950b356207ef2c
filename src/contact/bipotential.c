#include "ind_bipotential.h"

const char *const IndContactStatusNames[] = {"open", "stick", "slip"};

void IndBipotentialPredictor(PetscReal mu, PetscReal rho, const PetscReal r[3], PetscReal gap,
  const PetscReal du_t[2], PetscReal tau[3])
{
  const PetscReal slip = PetscSqrtReal(du_t[0] * du_t[0] + du_t[1] * du_t[1]);

  tau[0] = r[0] - rho * (gap + mu * slip);
  tau[1] = r[1] - rho * du_t[0];
  tau[2] = r[2] - rho * du_t[1];
}

IndContactStatus IndBipotentialProject(PetscReal mu, const PetscReal tau[3], PetscReal r[3], PetscReal D[9])
{
  const PetscReal a = PetscSqrtReal(tau[1] * tau[1] + tau[2] * tau[2]);

  if (D)
    for (int k = 0; k < 9; ++k) D[k] = 0.0;
  if (mu == 0) { /* frictionless: no tangential reaction whatever the slip, so no tangential derivative */
    r[0] = PetscMax(tau[0], 0.0);
    r[1] = r[2] = 0.0;
    if (tau[0] <= 0) return IND_CONTACT_OPEN;
    if (D) D[0] = 1.0;
    return IND_CONTACT_SLIP;
  }
  if (mu * a <= -tau[0]) { /* separating: the polar cone */
    r[0] = r[1] = r[2] = 0.0;
    return IND_CONTACT_OPEN;
  }
  if (a <= mu * tau[0]) { /* sticking: inside the cone */
    for (int k = 0; k < 3; ++k) r[k] = tau[k];
    if (D) D[0] = D[4] = D[8] = 1.0;
    return IND_CONTACT_STICK;
  }
  {
    /* Sliding: onto the cone's mantle. The paper's eq. 54 prints + mu n; with compression positive
       it is - mu n, which gives |r_t| = mu r_n. a > 0 here, since a <= mu tau_n otherwise. */
    const PetscReal c = 1.0 / (1.0 + mu * mu), rn = c * (tau[0] + mu * a), s[2] = {tau[1] / a, tau[2] / a};
    r[0] = rn;
    r[1] = mu * rn * s[0];
    r[2] = mu * rn * s[1];
    if (D) {
      D[0] = c;
      for (int i = 0; i < 2; ++i) {
        D[1 + i]       = mu * c * s[i];
        D[3 * (1 + i)] = mu * c * s[i];
        for (int j = 0; j < 2; ++j) D[3 * (1 + i) + 1 + j] = mu * mu * c * s[i] * s[j] + mu * rn / a * ((i == j ? 1.0
          : 0.0) - s[i] * s[j]);
      }
    }
    return IND_CONTACT_SLIP;
  }
}
