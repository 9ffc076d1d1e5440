/* The engine's lowest eigenpair of Eq. inst1 (modal form), LANES points at a time, or one.

   The contract of every entry point (arguments, dimensions, INFO) is _modal_kernel.h.

   The same algorithm as the numpy reference of spectral_rod/rod/collocation/eigensolver.py
   (_ShiftedModal and lowest_eigenpair; its docstrings explain it) for a stack of points:
   the Schur complement S of K - SHIFT, its LU factors, shift-and-invert steps on right and
   left vectors and the first-order convergence test. The arithmetic of LANES points runs side
   by side: every array below is laid out [index][lane], so each inner loop is over the lanes
   and the compiler vectorises it (points are independent; one point's own loops are short
   and dependent, so a loop per point gains little over numpy: tests/bench/c_prototype).

   Differences from the numpy reference, both checked per point: the LU has no pivoting (S is
   a Schur complement of K - SHIFT with SHIFT below every physical eigenvalue, far from
   singular; as spectral_rod/rod/collocation/stacked_inverse.py, a probe's backward error accepts
   the factors or rejects the point, status MODAL_REJECTED, and the caller solves it by the
   numpy reference), and a finished point stays in its group of LANES until the group is done
   (its results are taken when it finishes).

   Loaded with ctypes by spectral_rod/rod/collocation/modal_kernel.py; the Python module stub at
   the end only makes the build an importable extension. */

#define PY_SSIZE_T_CLEAN
#include <Python.h> /* first, as Python's headers require; used only by the module stub */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "_modal_kernel.h"

#define LANES 32

/* Where GCC and glibc allow it (ifunc), the kernel is compiled for three instruction sets and
   the best one the CPU has is picked at load time; every helper is inlined into it. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__GLIBC__)
#define CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define CLONES
#endif
#if defined(__GNUC__)
#define INLINE static inline __attribute__((always_inline))
#else
#define INLINE static inline
#endif

enum { NOT_CONVERGED = MODAL_NOT_CONVERGED, CONVERGED = MODAL_CONVERGED, ABOVE = MODAL_ABOVE,
       REJECTED = MODAL_REJECTED };

/* Workspace aligned to 64 bytes, the widest vector loads' width (AVX-512): with malloc's
   16-byte alignment every such load of the [index][lane] arrays can straddle two cache lines,
   depending on the heap's state, which made the same call's time vary between processes.
   NULL if the allocation fails. */
#if defined(_WIN32)
#include <malloc.h>
static double *workspace(size_t count) { return _aligned_malloc(count * sizeof(double), 64); }
static void release(double *p) { _aligned_free(p); }
#else
static double *workspace(size_t count) {
  void *p = NULL;
  return posix_memalign(&p, 64, count * sizeof(double)) ? NULL : p;
}
static void release(double *p) { free(p); }
#endif

/* Every function below takes the lane count L (LANES for a batch, 1 for a single point) as a
   constant at its inlined call site, so that its lane loops compile to vector code (or to
   scalar code for L = 1); arrays of one value per lane are sized LANES, the largest L. */
#define AT(m, i) ((m) + (size_t)(i) * L)

/* S[r][c] = delta_rc d_s[r] - a b sum_j g_se[r][j] r_e[j] g_es[j][c], then S = L U in place
   (unit L below the diagonal, 1/U_cc on it); a copy of S in s0 for the check. */
INLINE void factorise(const int L, int ke, int ks, const double *re, const double *ab, const double *ds,
                      const double *g_es, const double *g_se, double *s, double *s0) {
  for (int r = 0; r < ks; r++) {
    for (int c = 0; c < ks; c++) {
      double *src = AT(s, r * ks + c);
      for (int w = 0; w < L; w++) src[w] = 0.0;
    }
    for (int j = 0; j < ke; j++) {
      double cw[LANES];
      const double g = g_se[r * ke + j], *rj = AT(re, j), *gj = g_es + (size_t)j * ks;
      for (int w = 0; w < L; w++) cw[w] = -ab[w] * g * rj[w];
      for (int c = 0; c < ks; c++) {
        double *src = AT(s, r * ks + c);
        const double gc = gj[c];
        for (int w = 0; w < L; w++) src[w] += cw[w] * gc;
      }
    }
    double *srr = AT(s, r * ks + r);
    const double *dr = AT(ds, r);
    for (int w = 0; w < L; w++) srr[w] += dr[w];
  }
  memcpy(s0, s, sizeof(double) * L * ks * ks);
  for (int c = 0; c < ks; c++) {
    double *scc = AT(s, c * ks + c), inv[LANES];
    for (int w = 0; w < L; w++) scc[w] = inv[w] = 1.0 / scc[w];
    for (int r = c + 1; r < ks; r++) {
      double *src = AT(s, r * ks + c), l[LANES];
      for (int w = 0; w < L; w++) src[w] = l[w] = src[w] * inv[w];
      for (int j = c + 1; j < ks; j++) {
        double *srj = AT(s, r * ks + j);
        const double *scj = AT(s, c * ks + j);
        for (int w = 0; w < L; w++) srj[w] -= l[w] * scj[w];
      }
    }
  }
}

/* t = S^{-1} t from the factors */
INLINE void lu_solve(const int L, int ks, const double *s, double *t) {
  for (int r = 1; r < ks; r++) {
    double *tr = AT(t, r);
    for (int j = 0; j < r; j++) {
      const double *l = AT(s, r * ks + j), *tj = AT(t, j);
      for (int w = 0; w < L; w++) tr[w] -= l[w] * tj[w];
    }
  }
  for (int r = ks - 1; r >= 0; r--) {
    double *tr = AT(t, r);
    for (int j = r + 1; j < ks; j++) {
      const double *u = AT(s, r * ks + j), *tj = AT(t, j);
      for (int w = 0; w < L; w++) tr[w] -= u[w] * tj[w];
    }
    const double *d = AT(s, r * ks + r);
    for (int w = 0; w < L; w++) tr[w] *= d[w];
  }
}

/* t = S^{-T} t from the factors (S^T = U^T L^T) */
INLINE void lu_solve_transposed(const int L, int ks, const double *s, double *t) {
  for (int r = 0; r < ks; r++) {
    double *tr = AT(t, r);
    for (int j = 0; j < r; j++) {
      const double *u = AT(s, j * ks + r), *tj = AT(t, j);
      for (int w = 0; w < L; w++) tr[w] -= u[w] * tj[w];
    }
    const double *d = AT(s, r * ks + r);
    for (int w = 0; w < L; w++) tr[w] *= d[w];
  }
  for (int r = ks - 1; r >= 0; r--) {
    double *tr = AT(t, r);
    for (int j = r + 1; j < ks; j++) {
      const double *l = AT(s, j * ks + r), *tj = AT(t, j);
      for (int w = 0; w < L; w++) tr[w] -= l[w] * tj[w];
    }
  }
}

INLINE double nan_max(double a, double b) { return (b > a || b != b) ? b : a; }

/* Whether the factors pass the probe test of stacked_inverse.py, per lane:
   |S0 x - v| <= tol max|diag S0| |x| (max norms), x = S^{-1} v; nan or inf fails. */
INLINE void probe_check(const int L, int ks, const double *s, const double *s0, double tol, double *t,
                        int *ok) {
  double res[LANES], xmax[LANES], dmax[LANES];
  for (int c = 0; c < ks; c++) {
    const double v = (1.0 + (ks > 1 ? (double)c / (ks - 1) : 0.0)) * (c % 2 ? -1.0 : 1.0);
    double *tc = AT(t, c);
    for (int w = 0; w < L; w++) tc[w] = v;
  }
  lu_solve(L, ks, s, t);
  for (int w = 0; w < L; w++) res[w] = xmax[w] = dmax[w] = 0.0;
  for (int r = 0; r < ks; r++) {
    const double v = (1.0 + (ks > 1 ? (double)r / (ks - 1) : 0.0)) * (r % 2 ? -1.0 : 1.0);
    double acc[LANES];
    for (int w = 0; w < L; w++) acc[w] = -v;
    for (int c = 0; c < ks; c++) {
      const double *a = AT(s0, r * ks + c), *tc = AT(t, c);
      for (int w = 0; w < L; w++) acc[w] += a[w] * tc[w];
    }
    const double *d = AT(s0, r * ks + r), *tr = AT(t, r);
    for (int w = 0; w < L; w++) {  /* maxima that keep a nan (fmax would drop it) */
      res[w] = nan_max(res[w], fabs(acc[w]));
      xmax[w] = nan_max(xmax[w], fabs(tr[w]));
      dmax[w] = nan_max(dmax[w], fabs(d[w]));
    }
  }
  for (int w = 0; w < L; w++)
    ok[w] = isfinite(xmax[w]) && isfinite(dmax[w]) && res[w] <= tol * dmax[w] * xmax[w];
}

/* x = (K - SHIFT)^{-1} p (transposed: (K - SHIFT)^{-T}), in the modal blocks e and s:
   u = p_e r_e; x_s = S^{-1} (p_s - b G_se u); x_e = u - a r_e G_es x_s (a and b, G_es and
   G_se exchanged, S^{-T}, for the transpose) */
INLINE void shifted_solve(const int L, int ke, int ks, const double *s, const double *re, const double *a,
                          const double *b, const double *g_es, const double *g_se,
                          int transposed, const double *pe, const double *ps, double *xe,
                          double *xs) {
  for (int j = 0; j < ke; j++) {
    double *xj = AT(xe, j);
    const double *pj = AT(pe, j), *rj = AT(re, j);
    for (int w = 0; w < L; w++) xj[w] = pj[w] * rj[w];
  }
  for (int r = 0; r < ks; r++) {  /* (G u)_r: G_se u, or G_es^T u */
    double acc[LANES] = {0.0};
    for (int j = 0; j < ke; j++) {
      const double g = transposed ? g_es[(size_t)j * ks + r] : g_se[(size_t)r * ke + j];
      const double *xj = AT(xe, j);
      for (int w = 0; w < L; w++) acc[w] += g * xj[w];
    }
    double *xr = AT(xs, r);
    const double *pr = AT(ps, r), *c = transposed ? a : b;
    for (int w = 0; w < L; w++) xr[w] = pr[w] - c[w] * acc[w];
  }
  if (transposed) lu_solve_transposed(L, ks, s, xs); else lu_solve(L, ks, s, xs);
  for (int j = 0; j < ke; j++) {  /* (G x_s)_j: G_es x_s, or G_se^T x_s */
    double acc[LANES] = {0.0};
    for (int r = 0; r < ks; r++) {
      const double g = transposed ? g_se[(size_t)r * ke + j] : g_es[(size_t)j * ks + r];
      const double *xr = AT(xs, r);
      for (int w = 0; w < L; w++) acc[w] += g * xr[w];
    }
    double *xj = AT(xe, j);
    const double *rj = AT(re, j), *c = transposed ? b : a;
    for (int w = 0; w < L; w++) xj[w] -= c[w] * acc[w] * rj[w];
  }
}

/* The convergence test of lowest_eigenpair at every lane at once: normalises x and y, sets
   the two-sided quotient rq and the first-order error bound (per lane, the operations and
   their order of the numpy code's test). */
INLINE void lanes_test(const int L, int ke, int ks, double shift, double *xe, double *xs,
                       double *ye, double *ys, const double *pe, const double *ps,
                       const double *qe, const double *qs, double *rq, double *bound) {
  double sx[LANES], sy[LANES], se[LANES], ss[LANES], te[LANES], ts[LANES];
  double yx[LANES], ykx[LANES], rx[LANES], ry[LANES];
  for (int w = 0; w < L; w++) se[w] = ss[w] = te[w] = ts[w] = 0.0;
  for (int j = 0; j < ke; j++) {
    const double *x = AT(xe, j), *y = AT(ye, j);
    for (int w = 0; w < L; w++) { se[w] += x[w] * x[w]; te[w] += y[w] * y[w]; }
  }
  for (int j = 0; j < ks; j++) {
    const double *x = AT(xs, j), *y = AT(ys, j);
    for (int w = 0; w < L; w++) { ss[w] += x[w] * x[w]; ts[w] += y[w] * y[w]; }
  }
  for (int w = 0; w < L; w++) {
    sx[w] = 1.0 / sqrt(se[w] + ss[w]);
    sy[w] = 1.0 / sqrt(te[w] + ts[w]);
    yx[w] = ykx[w] = rx[w] = ry[w] = 0.0;
  }
  for (int blk = 0; blk < 2; blk++) {
    const int k = blk ? ks : ke;
    double *x = blk ? xs : xe, *y = blk ? ys : ye;
    const double *p = blk ? ps : pe;
    for (int j = 0; j < k; j++) {
      double *xj = AT(x, j), *yj = AT(y, j);
      const double *pj = AT(p, j);
      for (int w = 0; w < L; w++) {
        xj[w] *= sx[w];
        yj[w] *= sy[w];
        yx[w] += yj[w] * xj[w];
        ykx[w] += yj[w] * (shift * xj[w] + pj[w] * sx[w]);
      }
    }
  }
  for (int w = 0; w < L; w++) rq[w] = ykx[w] / yx[w];
  for (int blk = 0; blk < 2; blk++) {
    const int k = blk ? ks : ke;
    const double *x = blk ? xs : xe, *y = blk ? ys : ye, *p = blk ? ps : pe,
                 *q = blk ? qs : qe;
    for (int j = 0; j < k; j++) {
      const double *xj = AT(x, j), *yj = AT(y, j), *pj = AT(p, j), *qj = AT(q, j);
      for (int w = 0; w < L; w++) {
        const double u = shift * xj[w] + pj[w] * sx[w] - rq[w] * xj[w];
        const double v = shift * yj[w] + qj[w] * sy[w] - rq[w] * yj[w];
        rx[w] += u * u;
        ry[w] += v * v;
      }
    }
  }
  for (int w = 0; w < L; w++) bound[w] = sqrt(rx[w] * ry[w]) / fabs(yx[w]);
}

INLINE void put_lane(const int L, int k, const double *v, int w, double *out) {
  for (int j = 0; j < k; j++) out[j] = AT(v, j)[w];
}

/* One group of `count` <= LANES points of `in` starting at point i0 (lanes past count repeat
   the last point and are ignored). */
INLINE void solve_group(const int L, int i0, int count, const ModalBatch *in,
                        const ModalControl *ctl, double *work, const ModalEigenpairs *out) {
  const int ke = in->ke, ks = in->ks;
  const double *a = in->a, *b = in->b, *g_es = in->g_es, *g_se = in->g_se;
  const double shift = ctl->shift;
  int *status = out->status;
  double *s = work, *s0 = s + (size_t)L * ks * ks, *re = s0 + (size_t)L * ks * ks;
  double *ds = re + (size_t)L * ke, *xe = ds + (size_t)L * ks;
  double *ye = xe + (size_t)L * ke, *pe = ye + (size_t)L * ke;
  double *qe = pe + (size_t)L * ke, *xs = qe + (size_t)L * ke;
  double *ys = xs + (size_t)L * ks, *ps = ys + (size_t)L * ks;
  double *qs = ps + (size_t)L * ks, *t = qs + (size_t)L * ks;
  double al[LANES], bl[LANES], ab[LANES];
  int done[LANES], ok[LANES];
  for (int w = 0; w < L; w++) {
    const int i = i0 + (w < count ? w : count - 1);
    al[w] = a[i];
    bl[w] = b[i];
    ab[w] = a[i] * b[i];
    for (int j = 0; j < ke; j++) AT(re, j)[w] = in->r_e[(size_t)i * ke + j];
    for (int j = 0; j < ks; j++) AT(ds, j)[w] = in->d_s[(size_t)i * ks + j];
  }
  factorise(L, ke, ks, re, ab, ds, g_es, g_se, s, s0);
  probe_check(L, ks, s, s0, ctl->backward_tol, t, ok);
  for (int w = 0; w < L; w++) {
    done[w] = w >= count || !ok[w];
    if (w < count && !ok[w]) status[i0 + w] = REJECTED;
  }
  for (int j = 0; j < ke; j++)
    for (int w = 0; w < L; w++) AT(xe, j)[w] = AT(ye, j)[w] = in->start_e[j];
  for (int j = 0; j < ks; j++)
    for (int w = 0; w < L; w++) AT(xs, j)[w] = AT(ys, j)[w] = in->start_s[j];
  const int first = ctl->first, max_steps = ctl->max_steps;
  const double rtol = ctl->rtol, *ceiling = in->ceiling;
  for (int step = 1; step <= max_steps; step++) {
    memcpy(pe, xe, sizeof(double) * L * ke);
    memcpy(ps, xs, sizeof(double) * L * ks);
    memcpy(qe, ye, sizeof(double) * L * ke);
    memcpy(qs, ys, sizeof(double) * L * ks);
    shifted_solve(L, ke, ks, s, re, al, bl, g_es, g_se, 0, pe, ps, xe, xs);
    shifted_solve(L, ke, ks, s, re, al, bl, g_es, g_se, 1, qe, qs, ye, ys);
    if (step < first || step % 2) continue;
    int all = 1;
    double rq[LANES], bound[LANES];
    lanes_test(L, ke, ks, shift, xe, xs, ye, ys, pe, ps, qe, qs, rq, bound);
    for (int w = 0; w < L; w++) {
      if (done[w]) continue;
      const int i = i0 + w;
      const int conv = bound[w] <= rtol * fabs(rq[w]) && rq[w] >= shift;
      const int high = !conv && ceiling && rq[w] - 100.0 * bound[w] > ceiling[i];
      if (conv || high || step + 2 > max_steps) {
        done[w] = 1;
        out->lam[i] = rq[w];
        status[i] = conv ? CONVERGED : high ? ABOVE : NOT_CONVERGED;
        put_lane(L, ke, xe, w, out->x_e + (size_t)i * ke);
        put_lane(L, ks, xs, w, out->x_s + (size_t)i * ks);
        put_lane(L, ke, ye, w, out->y_e + (size_t)i * ke);
        put_lane(L, ks, ys, w, out->y_s + (size_t)i * ks);
      } else {
        all = 0;
      }
    }
    if (all) break;
  }
}

/* The lowest eigenpair of P points of one family (_modal_kernel.h). */
CLONES int modal_lowest(const ModalBatch *batch, const ModalControl *control,
                        ModalEigenpairs *out) {
  if (!batch || batch->P < 0 || batch->ke < 1 || batch->ks < 1 ||
      (batch->P && (!batch->r_e || !batch->a || !batch->b || !batch->d_s)) || !batch->g_es ||
      !batch->g_se || !batch->start_e || !batch->start_s)
    return -1;
  if (!control || control->first < 1 || control->max_steps < control->first) return -2;
  if (!out || (batch->P && (!out->lam || !out->x_e || !out->x_s || !out->y_e || !out->y_s ||
                            !out->status)))
    return -3;
  const size_t ke = batch->ke, ks = batch->ks;
  double *work = workspace(LANES * (2 * ks * ks + 5 * ke + 6 * ks));
  if (!work) return 1;
  for (int i0 = 0; i0 < batch->P; i0 += LANES)
    solve_group(LANES, i0, batch->P - i0 < LANES ? batch->P - i0 : LANES, batch, control, work,
                out);
  release(work);
  return 0;
}

int modal_lanes(void) { return LANES; }

int modal_abi_version(void) { return MODAL_KERNEL_ABI; }

const char *modal_isa(void) {
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__GLIBC__)
  /* the order of target_clones' choice: the first level the CPU supports */
  __builtin_cpu_init();
  if (__builtin_cpu_supports("x86-64-v4")) return "x86-64-v4";
  if (__builtin_cpu_supports("x86-64-v3")) return "x86-64-v3";
  return "default";
#else
  return "portable";
#endif
}

size_t modal_struct_size(int which) {
  switch (which) {
    case 0: return sizeof(ModalControl);
    case 1: return sizeof(ModalBatch);
    case 2: return sizeof(ModalEigenpairs);
    case 3: return sizeof(Family);
    case 4: return sizeof(ModalPoints);
    case 5: return sizeof(ModalPointResults);
    case 6: return sizeof(PencilForms);
    default: return 0;
  }
}

/* The pencil's bilinear forms y_e^T M_t x_f in double-double, for the two-sided Rayleigh
   quotient at large twist (eigensolver.pencil_rayleigh_quotient, Eq. inst1), where its terms
   cancel to ~lambda/Omega^2.

   Term t is the block `shape[t] = (e_off, m_e, f_off, m_f, data_off)`: the m_e x m_f matrix
   at mats + data_off (row-major), between rows e_off.. of y and columns f_off.. of x (both
   (P, m) row-major). Every product is split exactly (a b = p + e with p = fl(a b),
   e = fma(a, b, -p)) and every sum exactly (TwoSum), the errors accumulated apart (Ogita, Rump
   and Oishi's Dot2, 2005): hi + lo is the form as if computed in twice double precision.
   These splittings hold only for products rounded on their own: GCC, which by default fuses
   a product into a following sum, is told not to (clang fuses only within one expression,
   MSVC not at all). */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#endif

INLINE void two_sum(double a, double b, double *s, double *err) {
  const double x = a + b, z = x - a;
  *s = x;
  *err = (a - (x - z)) + (b - z);
}

/* The forms of `count` <= L points from i0 on (lanes past count repeat the last point). */
INLINE void terms_group(const int L, int i0, int count, int m, int T, const int *shape,
                        const double *mats, const double *x, const double *y, double *xt,
                        double *yt, double *hi, double *lo) {
  for (int w = 0; w < L; w++) {
    const int i = i0 + (w < count ? w : count - 1);
    for (int k = 0; k < m; k++) {
      AT(xt, k)[w] = x[(size_t)i * m + k];
      AT(yt, k)[w] = y[(size_t)i * m + k];
    }
  }
  for (int t = 0; t < T; t++) {
    const int e_off = shape[5 * t], m_e = shape[5 * t + 1], f_off = shape[5 * t + 2];
    const int m_f = shape[5 * t + 3];
    const double *mat = mats + shape[5 * t + 4];
    double acc[LANES] = {0.0}, acc_lo[LANES] = {0.0};
    for (int j = 0; j < m_e; j++) {
      double s[LANES] = {0.0}, c[LANES] = {0.0};
      for (int k = 0; k < m_f; k++) {  /* (M x)_j = s + c */
        const double a = mat[(size_t)j * m_f + k], *xk = AT(xt, f_off + k);
        for (int w = 0; w < L; w++) {
          const double p = a * xk[w], e = fma(a, xk[w], -p);
          double err;
          two_sum(s[w], p, &s[w], &err);
          c[w] += err + e;
        }
      }
      const double *yj = AT(yt, e_off + j);
      for (int w = 0; w < L; w++) {  /* acc += y_j (s + c) */
        const double p = yj[w] * s[w], e = fma(yj[w], s[w], -p);
        double err;
        two_sum(acc[w], p, &acc[w], &err);
        acc_lo[w] += err + e + yj[w] * c[w];
      }
    }
    for (int w = 0; w < count; w++) {
      hi[(size_t)(i0 + w) * T + t] = acc[w];
      lo[(size_t)(i0 + w) * T + t] = acc_lo[w];
    }
  }
}

/* All P points: LANES at a time, a last group of fewer one at a time (a single point, as in a
   scalar call, would otherwise cost a whole group). */
CLONES int pencil_terms_dd(PencilForms *f) {
  if (!f || f->P < 0 || f->m < 0 || f->T < 1 ||
      (f->P && (!f->shape || !f->mats || !f->x || !f->y || !f->hi || !f->lo)))
    return -1;
  const int P = f->P, m = f->m, T = f->T;
  double *xt = workspace(LANES * 2 * (size_t)(m > 0 ? m : 1));
  if (!xt) return 1;
  double *yt = xt + (size_t)LANES * m;
  int i0 = 0;
  for (; P - i0 >= LANES; i0 += LANES)
    terms_group(LANES, i0, LANES, m, T, f->shape, f->mats, f->x, f->y, xt, yt, f->hi, f->lo);
  for (; i0 < P; i0++)
    terms_group(1, i0, 1, m, T, f->shape, f->mats, f->x, f->y, xt, yt, f->hi, f->lo);
  release(xt);
  return 0;
}
/* y^T A x / y^T B x for one point in double-double: the terms' forms as above, their sum
   weighted by the coefficients (c + c_lo) and the mass terms' sum, then the quotient; the
   batched engine sums the same forms in long double (eigensolver._rayleigh_sums). Not inlined:
   it keeps this region's floating-point contraction off. `scratch` holds 2 terms + 2 m. */
static double quotient_dd(int m, int T, const int *shape, const double *mats, const int *mass,
                          const double *c, const double *c_lo, const double *x, const double *y,
                          double *scratch) {
  double *hi = scratch, *lo = hi + T, *xt = lo + T, *yt = xt + m;
  terms_group(1, 0, 1, m, T, shape, mats, x, y, xt, yt, hi, lo);
  double nh = 0.0, nl = 0.0, dh = 0.0, dl = 0.0, err;
  for (int t = 0; t < T; t++) {
    const double p = c[t] * hi[t], e = fma(c[t], hi[t], -p);
    two_sum(nh, p, &nh, &err);
    nl += err + e + c[t] * lo[t] + c_lo[t] * hi[t];
    if (mass[t]) {
      two_sum(dh, hi[t], &dh, &err);
      dl += err + lo[t];
    }
  }
  const double q = nh / dh;  /* (nh + nl) / (dh + dl) to first order in the low parts */
  return q + ((fma(-q, dh, nh) + nl) - q * dl) / dh;
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC pop_options
#endif

/* The pencil's two-sided Rayleigh quotient y^T A x / y^T B x of one point (Eq. inst1's terms
   weighted by their coefficients over the mass terms): the kernel's one pencil quotient, its
   precision a parameter, double where coef_lo is NULL, double-double (quotient_dd) where it
   gives the coefficients' low parts. The numpy reference's is
   eigensolver.pencil_rayleigh_quotient, with its dtype as the precision. Inlined, so that the
   double sums compile for the instruction set of the clone that calls it. */
INLINE double pencil_quotient(const Family *f, int terms, const double *coef,
                              const double *coef_lo, const double *x, const double *y,
                              double *scratch) {
  const int m = f->k1 + f->k2;
  if (coef_lo)
    return quotient_dd(m, terms, f->term_shape, f->term_mats, f->mass, coef, coef_lo, x, y,
                       scratch);
  double num = 0.0, den = 0.0;
  for (int t = 0; t < terms; t++) {
    const int *sh = f->term_shape + 5 * t;
    const double *mat = f->term_mats + sh[4];
    double acc = 0.0;
    for (int j = 0; j < sh[1]; j++) {
      double row = 0.0;
      for (int k = 0; k < sh[3]; k++) row += mat[(size_t)j * sh[3] + k] * x[sh[2] + k];
      acc += y[sh[0] + j] * row;
    }
    num += coef[t] * acc;
    if (f->mass[t]) den += acc;
  }
  return num / den;
}

/* One family at one point: the lowest eigenpair by the kernel (one lane), then the pencil's
   vectors, the tail and, unless control->loose, the pencil's two-sided Rayleigh quotient: in
   double, or where coef_lo (the coefficients' low parts) is given in double-double
   (quotient_dd). */
INLINE void family_point(const Family *f, int terms, const double *coef, const double *coef_lo,
                         const double *ceiling, const ModalControl *ctl, double *work,
                         double *lam, double *tail, int *status) {
  const int k1 = f->k1, k2 = f->k2, m = k1 + k2, e1 = f->schur == 2;
  const int ke = e1 ? k1 : k2, ks = e1 ? k2 : k1;
  const double shift = ctl->shift;
  const int loose = ctl->loose;
  double *r_e = work, *d_s = r_e + ke, *v = d_s + ks, *x = v + 2 * m, *y = x + m;
  double *rest = y + m;  /* solve_group's workspace, one lane */
  const double *lam_e = e1 ? f->lam1 : f->lam2, *lam_s = e1 ? f->lam2 : f->lam1;
  const int qe = e1 ? 0 : 1, qs = 1 - qe;  /* equations of the e and s blocks */
  for (int j = 0; j < ke; j++)
    r_e[j] = 1.0 / (coef[f->own0[qe]] - coef[f->own2[qe]] * lam_e[j] - shift);
  for (int j = 0; j < ks; j++) d_s[j] = coef[f->own0[qs]] - coef[f->own2[qs]] * lam_s[j] - shift;
  const double a = 2.0 * coef[f->coupling[qe]], b = 2.0 * coef[f->coupling[qs]];
  double *ze = v, *zs = v + ke, *we = v + m, *ws = v + m + ke;
  const ModalBatch one = {1, ke, ks, r_e, &a, &b, d_s, e1 ? f->g12 : f->g21,
                          e1 ? f->g21 : f->g12, f->start + (e1 ? 0 : k1),
                          f->start + (e1 ? k1 : 0), ceiling};
  const ModalEigenpairs res = {lam, ze, zs, we, ws, status};
  solve_group(1, 0, 1, &one, ctl, rest, &res);
  *tail = INFINITY;
  if (*status != CONVERGED) return;
  const double *z1 = e1 ? ze : zs, *z2 = e1 ? zs : ze, *w1 = e1 ? we : ws, *w2 = e1 ? ws : we;
  for (int r = 0; r < m; r++) {  /* x = (U1 z1, U2 z2), y = (left1^T w1, left2^T w2) */
    const int blk = r >= k1, k = blk ? k2 : k1, rr = blk ? r - k1 : r;
    const double *u = blk ? f->u2 : f->u1, *lf = blk ? f->left2 : f->left1;
    const double *z = blk ? z2 : z1, *w = blk ? w2 : w1;
    double sx = 0.0, sy = 0.0;
    for (int j = 0; j < k; j++) {
      sx += u[(size_t)rr * k + j] * z[j];
      sy += w[j] * lf[(size_t)j * k + rr];
    }
    x[r] = sx;
    y[r] = sy;
  }
  double last = 0.0, other = 0.0;  /* resolution.tail_parts and tail_from_parts */
  for (int r = 0; r < f->tail_count; r++) {
    double c = 0.0;
    for (int j = 0; j < m; j++) c += f->tail_rows[(size_t)r * m + j] * x[j];
    if (r < 4) last = nan_max(last, fabs(c)); else other = nan_max(other, fabs(c));
  }
  const double scale = nan_max(last, other);
  *tail = scale > 0.0 ? last / scale : INFINITY;
  if (!isfinite(last) || !isfinite(other)) *status = NOT_CONVERGED;
  if (loose) return;
  /* rest, solve_group's workspace, is free again: quotient_dd's scratch */
  *lam = pencil_quotient(f, terms, coef, coef_lo, x, y, rest);
  if (!(*lam >= shift)) *status = NOT_CONVERGED;  /* a nan quotient is not an answer */
}

/* Both families (symmetric first, the antisymmetric one only shown to lie above
   (1 + close_rel) times it where it does, as collocation._solve_points) at P points, one at
   a time (_modal_kernel.h); the antisymmetric family's tail is inf where it is above. */
CLONES int modal_points(const Family *fam, const ModalPoints *pts, const ModalControl *control,
                        ModalPointResults *out) {
  if (!fam) return -1;
  if (!pts || pts->P < 0 || pts->terms < 1 || (pts->P && !pts->coef)) return -2;
  if (!control || control->first < 1 || control->max_steps < control->first) return -3;
  if (!out || (pts->P && (!out->lam || !out->tail || !out->status))) return -4;
  size_t size = 0;
  for (int q = 0; q < 2; q++) {
    const size_t k = (size_t)fam[q].k1 + fam[q].k2;
    const size_t need = 5 * k + 2 * k * k + 5 * k + 6 * k;
    if (need > size) size = need;
  }
  double *work = workspace(size);
  if (!work) return 1;
  ModalControl anti = *control;  /* the antisymmetric family may stop early: an earlier test */
  if (anti.first > 4) anti.first = 4;
  const int terms = pts->terms;
  for (int i = 0; i < pts->P; i++) {
    const double *c = pts->coef + (size_t)i * terms;
    const double *c_lo = pts->coef_lo ? pts->coef_lo + (size_t)i * terms : NULL;
    double *lam = out->lam + 2 * i, *tail = out->tail + 2 * i;
    int *status = out->status + 2 * i;
    family_point(&fam[0], terms, c, c_lo, NULL, control, work, lam, tail, status);
    const double ceiling = lam[0] * (1.0 + control->close_rel);
    family_point(&fam[1], terms, c, c_lo, status[0] == CONVERGED ? &ceiling : NULL, &anti,
                 work, lam + 1, tail + 1, status + 1);
  }
  release(work);
  return 0;
}


/* The module stub: the build is an importable extension (so that setuptools builds it on every
   platform); the kernel itself is called through ctypes. */

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_modal_kernel",
    "C kernel of the batched engine (loaded with ctypes).", -1, NULL, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit__modal_kernel(void) { return PyModule_Create(&module); }
