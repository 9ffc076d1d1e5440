/* The batched engine's lowest eigenpair as plain C loops per point: a measurement for issue 14
   (tests/bench/c_prototype/measure.py), not part of the package. */
#include <math.h>
#include <string.h>
#define KMAX 80
static void lu(int k, double *S, int *piv) {
  for (int c = 0; c < k; c++) {
    int p = c; double m = fabs(S[c*k+c]);
    for (int r = c+1; r < k; r++) if (fabs(S[r*k+c]) > m) { m = fabs(S[r*k+c]); p = r; }
    piv[c] = p;
    if (p != c) for (int j = 0; j < k; j++) { double t = S[c*k+j]; S[c*k+j] = S[p*k+j]; S[p*k+j] = t; }
    double inv = 1.0 / S[c*k+c];
    for (int r = c+1; r < k; r++) {
      double l = S[r*k+c] * inv; S[r*k+c] = l;
      if (l != 0.0) for (int j = c+1; j < k; j++) S[r*k+j] -= l * S[c*k+j];
    }
  }
}
static void lusolve(int k, const double *S, const int *piv, double *x) {
  for (int c = 0; c < k; c++) { int p = piv[c]; if (p != c) { double t = x[c]; x[c] = x[p]; x[p] = t; } }
  for (int r = 1; r < k; r++) { double s = x[r]; for (int j = 0; j < r; j++) s -= S[r*k+j]*x[j]; x[r] = s; }
  for (int r = k-1; r >= 0; r--) { double s = x[r]; for (int j = r+1; j < k; j++) s -= S[r*k+j]*x[j]; x[r] = s / S[r*k+r]; }
}
static void lusolveT(int k, const double *S, const int *piv, double *x) {
  /* solve S^T x = b where P S = L U  ->  S^T = U^T L^T P */
  for (int r = 0; r < k; r++) { double s = x[r]; for (int j = 0; j < r; j++) s -= S[j*k+r]*x[j]; x[r] = s / S[r*k+r]; }
  for (int r = k-1; r >= 0; r--) { double s = x[r]; for (int j = r+1; j < k; j++) s -= S[j*k+r]*x[j]; x[r] = s; }
  for (int c = k-1; c >= 0; c--) { int p = piv[c]; if (p != c) { double t = x[c]; x[c] = x[p]; x[p] = t; } }
}
int lowest(int P, int ke, int ks, const double *r_e, const double *a, const double *b,
           const double *d_s, const double *g_es, const double *g_se,
           const double *start_e, const double *start_s, double shift, double rtol,
           int first, int max_steps, double *lam, int *steps_out) {
  double S[KMAX*KMAX]; int piv[KMAX];
  double xe[KMAX], xs[KMAX], ye[KMAX], ys[KMAX], pe[KMAX], ps[KMAX], qe[KMAX], qs[KMAX], t[KMAX];
  for (int i = 0; i < P; i++) {
    const double *re = r_e + (size_t)i*ke; double ai = a[i], bi = b[i], ab = ai*bi;
    for (int r = 0; r < ks; r++) {
      double *Sr = S + r*ks;
      for (int c = 0; c < ks; c++) Sr[c] = 0.0;
      for (int j = 0; j < ke; j++) { double w = -ab * g_se[r*ke+j] * re[j]; const double *g = g_es + j*ks;
        for (int c = 0; c < ks; c++) Sr[c] += w * g[c]; }
      Sr[r] += d_s[(size_t)i*ks+r];
    }
    lu(ks, S, piv);
    memcpy(xe, start_e, ke*sizeof(double)); memcpy(xs, start_s, ks*sizeof(double));
    memcpy(ye, start_e, ke*sizeof(double)); memcpy(ys, start_s, ks*sizeof(double));
    lam[i] = NAN; steps_out[i] = -1;
    for (int step = 1; step <= max_steps; step++) {
      memcpy(pe, xe, ke*8); memcpy(ps, xs, ks*8); memcpy(qe, ye, ke*8); memcpy(qs, ys, ks*8);
      /* x = (K - shift)^{-1} x */
      for (int j = 0; j < ke; j++) xe[j] = pe[j] * re[j];
      for (int r = 0; r < ks; r++) { double s = 0; for (int j = 0; j < ke; j++) s += g_se[r*ke+j]*xe[j]; t[r] = ps[r] - bi*s; }
      lusolve(ks, S, piv, t); memcpy(xs, t, ks*8);
      for (int j = 0; j < ke; j++) { double s = 0; for (int c = 0; c < ks; c++) s += g_es[j*ks+c]*xs[c]; xe[j] -= ai*s*re[j]; }
      /* y = (K - shift)^{-T} y */
      for (int j = 0; j < ke; j++) ye[j] = qe[j] * re[j];
      for (int c = 0; c < ks; c++) { double s = 0; for (int j = 0; j < ke; j++) s += g_es[j*ks+c]*ye[j]; t[c] = qs[c] - ai*s; }
      lusolveT(ks, S, piv, t); memcpy(ys, t, ks*8);
      for (int j = 0; j < ke; j++) { double s = 0; for (int r = 0; r < ks; r++) s += g_se[r*ke+j]*ys[r]; ye[j] -= bi*s*re[j]; }
      if (step < first || step % 2) continue;
      double nx = 0, ny = 0;
      for (int j = 0; j < ke; j++) { nx += xe[j]*xe[j]; ny += ye[j]*ye[j]; }
      for (int j = 0; j < ks; j++) { nx += xs[j]*xs[j]; ny += ys[j]*ys[j]; }
      double sx = 1/sqrt(nx), sy = 1/sqrt(ny);
      double yx = 0, ykx = 0;
      for (int j = 0; j < ke; j++) { xe[j]*=sx; ye[j]*=sy; yx += ye[j]*xe[j]; ykx += ye[j]*(shift*xe[j] + pe[j]*sx); }
      for (int j = 0; j < ks; j++) { xs[j]*=sx; ys[j]*=sy; yx += ys[j]*xs[j]; ykx += ys[j]*(shift*xs[j] + ps[j]*sx); }
      double rq = ykx / yx, rx = 0, ry = 0;
      for (int j = 0; j < ke; j++) { double u = shift*xe[j] + pe[j]*sx - rq*xe[j]; rx += u*u; u = shift*ye[j] + qe[j]*sy - rq*ye[j]; ry += u*u; }
      for (int j = 0; j < ks; j++) { double u = shift*xs[j] + ps[j]*sx - rq*xs[j]; rx += u*u; u = shift*ys[j] + qs[j]*sy - rq*ys[j]; ry += u*u; }
      double bound = sqrt(rx*ry)/fabs(yx);
      if ((bound <= rtol*fabs(rq) && rq >= shift) || step + 2 > max_steps) { lam[i] = rq; steps_out[i] = step; break; }
    }
  }
  return 0;
}
