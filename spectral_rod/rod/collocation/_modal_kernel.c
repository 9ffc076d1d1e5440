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
INLINE void factorise(const int L, int ke, int ks, const double *re, const double *ab,
                      const double *ds, const double *g_es, const double *g_se, double *s,
                      double *s0) {
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
INLINE void probe_check(const int L, int ks, const double *s, const double *s0, double tol,
                        double *t, int *ok) {
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
INLINE void shifted_solve(const int L, int ke, int ks, const double *s, const double *re,
                          const double *a, const double *b, const double *g_es, const double *g_se,
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

/* r[j][w] = v[j][w] for the lanes w with fin[w] (k rows, lane layout; a select the compiler
   vectorises) */
INLINE void capture(const int L, int k, const double *v, const int *fin, double *r) {
  for (int j = 0; j < k; j++) {
    const double *vj = AT(v, j);
    double *rj = AT(r, j);
    for (int w = 0; w < L; w++) rj[w] = fin[w] ? vj[w] : rj[w];
  }
}

/* The iteration of one group of L lanes, all in lane layout ([index][lane]): the first `count`
   lanes are points (the others are ignored). Inputs: re (ke, L) = 1/(D_e - shift), ds (ks, L)
   = D_s - shift, the coupling factors al, bl (L,), G_es, G_se, the start vector's blocks and
   ceiling (L,) or NULL. Each lane's vectors, quotient and status are taken at the test where
   it finishes: rxe, rye (ke, L), rxs, rys (ks, L), lam (L,), status (L,). `work` holds
   2 ks^2 + 4 ke + 5 ks per lane. */
INLINE void iterate_lanes(const int L, int count, int ke, int ks, const double *re,
                          const double *al, const double *bl, const double *ds,
                          const double *g_es, const double *g_se, const double *start_e,
                          const double *start_s, const double *ceiling,
                          const ModalControl *ctl, double *work, double *rxe, double *rxs,
                          double *rye, double *rys, double *lam, int *status) {
  const double shift = ctl->shift;
  double *s = work, *s0 = s + (size_t)L * ks * ks, *xe = s0 + (size_t)L * ks * ks;
  double *ye = xe + (size_t)L * ke, *pe = ye + (size_t)L * ke;
  double *qe = pe + (size_t)L * ke, *xs = qe + (size_t)L * ke;
  double *ys = xs + (size_t)L * ks, *ps = ys + (size_t)L * ks;
  double *qs = ps + (size_t)L * ks, *t = qs + (size_t)L * ks;
  double ab[LANES];
  int done[LANES], ok[LANES], fin[LANES];
  for (int w = 0; w < L; w++) ab[w] = al[w] * bl[w];
  factorise(L, ke, ks, re, ab, ds, g_es, g_se, s, s0);
  probe_check(L, ks, s, s0, ctl->backward_tol, t, ok);
  for (int w = 0; w < L; w++) {
    done[w] = w >= count || !ok[w];
    if (w < count && !ok[w]) status[w] = REJECTED;
  }
  for (int j = 0; j < ke; j++)
    for (int w = 0; w < L; w++) AT(xe, j)[w] = AT(ye, j)[w] = start_e[j];
  for (int j = 0; j < ks; j++)
    for (int w = 0; w < L; w++) AT(xs, j)[w] = AT(ys, j)[w] = start_s[j];
  const int first = ctl->first, max_steps = ctl->max_steps;
  const double rtol = ctl->rtol;
  for (int step = 1; step <= max_steps; step++) {
    memcpy(pe, xe, sizeof(double) * L * ke);
    memcpy(ps, xs, sizeof(double) * L * ks);
    memcpy(qe, ye, sizeof(double) * L * ke);
    memcpy(qs, ys, sizeof(double) * L * ks);
    shifted_solve(L, ke, ks, s, re, al, bl, g_es, g_se, 0, pe, ps, xe, xs);
    shifted_solve(L, ke, ks, s, re, al, bl, g_es, g_se, 1, qe, qs, ye, ys);
    if (step < first || step % 2) continue;
    int all = 1, any = 0;
    double rq[LANES], bound[LANES];
    lanes_test(L, ke, ks, shift, xe, xs, ye, ys, pe, ps, qe, qs, rq, bound);
    for (int w = 0; w < L; w++) {
      fin[w] = 0;
      if (done[w]) continue;
      const int conv = bound[w] <= rtol * fabs(rq[w]) && rq[w] >= shift;
      const int high = !conv && ceiling && rq[w] - 100.0 * bound[w] > ceiling[w];
      if (conv || high || step + 2 > max_steps) {
        done[w] = fin[w] = any = 1;
        lam[w] = rq[w];
        status[w] = conv ? CONVERGED : high ? ABOVE : NOT_CONVERGED;
      } else {
        all = 0;
      }
    }
    if (any) {
      capture(L, ke, xe, fin, rxe);
      capture(L, ks, xs, fin, rxs);
      capture(L, ke, ye, fin, rye);
      capture(L, ks, ys, fin, rys);
    }
    if (all) break;
  }
}

INLINE void put_lane(const int L, int k, const double *v, int w, double *out) {
  for (int j = 0; j < k; j++) out[j] = AT(v, j)[w];
}

/* One group of `count` <= LANES points of `in` starting at point i0, rows in and out (lanes
   past count repeat the last point and are ignored). */
INLINE void solve_group(const int L, int i0, int count, const ModalBatch *in,
                        const ModalControl *ctl, double *work, const ModalEigenpairs *out) {
  const int ke = in->ke, ks = in->ks;
  double *re = work, *ds = re + (size_t)L * ke, *rxe = ds + (size_t)L * ks;
  double *rxs = rxe + (size_t)L * ke, *rye = rxs + (size_t)L * ks, *rys = rye + (size_t)L * ke;
  double *rest = rys + (size_t)L * ks;
  double al[LANES], bl[LANES], ceiling[LANES], lam[LANES];
  int status[LANES];
  for (int w = 0; w < L; w++) {
    const int i = i0 + (w < count ? w : count - 1);
    al[w] = in->a[i];
    bl[w] = in->b[i];
    ceiling[w] = in->ceiling ? in->ceiling[i] : 0.0;
    for (int j = 0; j < ke; j++) AT(re, j)[w] = in->r_e[(size_t)i * ke + j];
    for (int j = 0; j < ks; j++) AT(ds, j)[w] = in->d_s[(size_t)i * ks + j];
  }
  iterate_lanes(L, count, ke, ks, re, al, bl, ds, in->g_es, in->g_se, in->start_e,
                in->start_s, in->ceiling ? ceiling : NULL, ctl, rest, rxe, rxs, rye, rys, lam,
                status);
  for (int w = 0; w < count; w++) {
    const int i = i0 + w;
    out->status[i] = status[w];
    if (status[w] == REJECTED) continue;
    out->lam[i] = lam[w];
    put_lane(L, ke, rxe, w, out->x_e + (size_t)i * ke);
    put_lane(L, ks, rxs, w, out->x_s + (size_t)i * ks);
    put_lane(L, ke, rye, w, out->y_e + (size_t)i * ke);
    put_lane(L, ks, rys, w, out->y_s + (size_t)i * ks);
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
  double *work = workspace(LANES * (2 * ks * ks + 7 * ke + 8 * ks));
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

/* The forms of L lanes from vectors in lane layout, xt, yt (m, L): hi, lo (T, L). For L = 1
   the lane layout is a point's row. */
INLINE void terms_lanes(const int L, int T, const int *shape, const double *mats,
                        const double *xt, const double *yt, double *hi, double *lo) {
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
    for (int w = 0; w < L; w++) {
      AT(hi, t)[w] = acc[w];
      AT(lo, t)[w] = acc_lo[w];
    }
  }
}

/* The forms of `count` <= L points from i0 on, rows of x and y (lanes past count repeat the
   last point), into hi, lo (P, T); xt, yt hold (m, L), th 2 T L. */
INLINE void terms_group(const int L, int i0, int count, int m, int T, const int *shape,
                        const double *mats, const double *x, const double *y, double *xt,
                        double *yt, double *th, double *hi, double *lo) {
  for (int w = 0; w < L; w++) {
    const int i = i0 + (w < count ? w : count - 1);
    for (int k = 0; k < m; k++) {
      AT(xt, k)[w] = x[(size_t)i * m + k];
      AT(yt, k)[w] = y[(size_t)i * m + k];
    }
  }
  double *tl = th + (size_t)L * T;  /* th: the forms (T, L), tl their low parts */
  terms_lanes(L, T, shape, mats, xt, yt, th, tl);
  for (int t = 0; t < T; t++)
    for (int w = 0; w < count; w++) {
      hi[(size_t)(i0 + w) * T + t] = AT(th, t)[w];
      lo[(size_t)(i0 + w) * T + t] = AT(tl, t)[w];
    }
}

/* All P points: LANES at a time, a last group of fewer one at a time (a single point, as in a
   scalar call, would otherwise cost a whole group). */
CLONES int pencil_terms_dd(PencilForms *f) {
  if (!f || f->P < 0 || f->m < 0 || f->T < 1 ||
      (f->P && (!f->shape || !f->mats || !f->x || !f->y || !f->hi || !f->lo)))
    return -1;
  const int P = f->P, m = f->m, T = f->T;
  double *xt = workspace(LANES * (2 * (size_t)(m > 0 ? m : 1) + 2 * (size_t)T));
  if (!xt) return 1;
  double *yt = xt + (size_t)LANES * m, *th = yt + (size_t)LANES * m;
  int i0 = 0;
  for (; P - i0 >= LANES; i0 += LANES)
    terms_group(LANES, i0, LANES, m, T, f->shape, f->mats, f->x, f->y, xt, yt, th, f->hi,
                f->lo);
  for (; i0 < P; i0++)
    terms_group(1, i0, 1, m, T, f->shape, f->mats, f->x, f->y, xt, yt, th, f->hi, f->lo);
  release(xt);
  return 0;
}
/* y^T A x / y^T B x of L lanes in double-double: the terms' forms as above, their sum
   weighted by the coefficients (c + c_lo, each (T, L)) and the mass terms' sum, then the
   quotient; the batched numpy engine sums the same forms in long double
   (quotient._rayleigh_sums). x, y (m, L) in lane layout; `scratch` holds 2 T L. */
INLINE void quotient_dd(const int L, int T, const int *shape, const double *mats,
                        const int *mass, const double *c, const double *c_lo, const double *x,
                        const double *y, double *scratch, double *q) {
  double *hi = scratch, *lo = hi + (size_t)L * T;
  terms_lanes(L, T, shape, mats, x, y, hi, lo);
  for (int w = 0; w < L; w++) {
    double nh = 0.0, nl = 0.0, dh = 0.0, dl = 0.0, err;
    for (int t = 0; t < T; t++) {
      const double ct = AT(c, t)[w], ht = AT(hi, t)[w], lt = AT(lo, t)[w];
      const double p = ct * ht, e = fma(ct, ht, -p);
      two_sum(nh, p, &nh, &err);
      nl += err + e + ct * lt + AT(c_lo, t)[w] * ht;
      if (mass[t]) {
        two_sum(dh, ht, &dh, &err);
        dl += err + lt;
      }
    }
    const double r = nh / dh;  /* (nh + nl) / (dh + dl) to first order in the low parts */
    q[w] = r + ((fma(-r, dh, nh) + nl) - r * dl) / dh;
  }
}

/* quotient_dd for one lane and for LANES, compiled here, not inlined into their callers: this
   keeps the region's floating-point contraction off; both with the callers' clones, so that
   fma is an instruction and the LANES one is vectorised for the same instruction sets. */
CLONES static void quotient_dd_one(int T, const int *shape, const double *mats,
                                   const int *mass, const double *c, const double *c_lo,
                                   const double *x, const double *y, double *scratch,
                                   double *q) {
  quotient_dd(1, T, shape, mats, mass, c, c_lo, x, y, scratch, q);
}

CLONES static void quotient_dd_lanes(int T, const int *shape, const double *mats,
                                     const int *mass, const double *c, const double *c_lo,
                                     const double *x, const double *y, double *scratch,
                                     double *q) {
  quotient_dd(LANES, T, shape, mats, mass, c, c_lo, x, y, scratch, q);
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC pop_options
#endif

/* The pencil's two-sided Rayleigh quotient y^T A x / y^T B x of L lanes (Eq. inst1's terms
   weighted by their coefficients over the mass terms): the kernel's one pencil quotient, its
   precision a parameter, double where coef_lo is NULL, double-double (quotient_dd) where it
   gives the coefficients' low parts. coef, coef_lo (T, L); x, y (m, L); q (L,) out. The numpy
   reference's is quotient.pencil_rayleigh_quotient, with its dtype as the precision. */
INLINE void pencil_quotient(const int L, const Family *f, int terms, const double *coef,
                            const double *coef_lo, const double *x, const double *y,
                            double *scratch, double *q) {
  if (coef_lo) {
    if (L == 1)
      quotient_dd_one(terms, f->term_shape, f->term_mats, f->mass, coef, coef_lo, x, y,
                      scratch, q);
    else
      quotient_dd_lanes(terms, f->term_shape, f->term_mats, f->mass, coef, coef_lo, x, y,
                        scratch, q);
    return;
  }
  double num[LANES], den[LANES];
  for (int w = 0; w < L; w++) num[w] = den[w] = 0.0;
  for (int t = 0; t < terms; t++) {
    const int *sh = f->term_shape + 5 * t;
    const double *mat = f->term_mats + sh[4];
    double acc[LANES];
    for (int w = 0; w < L; w++) acc[w] = 0.0;
    for (int j = 0; j < sh[1]; j++) {
      double row[LANES];
      for (int w = 0; w < L; w++) row[w] = 0.0;
      for (int k = 0; k < sh[3]; k++) {
        const double a = mat[(size_t)j * sh[3] + k], *xk = AT(x, sh[2] + k);
        for (int w = 0; w < L; w++) row[w] += a * xk[w];
      }
      const double *yj = AT(y, sh[0] + j);
      for (int w = 0; w < L; w++) acc[w] += yj[w] * row[w];
    }
    const double *ct = AT(coef, t);
    for (int w = 0; w < L; w++) num[w] += ct[w] * acc[w];
    if (f->mass[t])
      for (int w = 0; w < L; w++) den[w] += acc[w];
  }
  for (int w = 0; w < L; w++) q[w] = num[w] / den[w];
}

/* v (k, L) = M (k, k) z (k, L), or M^T z where `transposed` */
INLINE void lanes_product(const int L, int k, const double *mat, int transposed,
                          const double *z, double *v) {
  for (int r = 0; r < k; r++) {
    double acc[LANES];
    for (int w = 0; w < L; w++) acc[w] = 0.0;
    for (int j = 0; j < k; j++) {
      const double a = transposed ? mat[(size_t)j * k + r] : mat[(size_t)r * k + j];
      const double *zj = AT(z, j);
      for (int w = 0; w < L; w++) acc[w] += a * zj[w];
    }
    double *vr = AT(v, r);
    for (int w = 0; w < L; w++) vr[w] = acc[w];
  }
}

/* One family at `count` <= L points (lanes past count repeat the last point; their results are
   not used): the lowest eigenpair by iterate_lanes, then, unless no lane converged (e.g. every
   antisymmetric lane shown above its ceiling: the tail is inf there), the pencil's vectors, the
   tail and, unless control->loose, the pencil's two-sided Rayleigh quotient: in double, or
   where coef_lo (the coefficients' low parts) is given in double-double (quotient_dd). coef,
   coef_lo (terms, L); ceiling (L,) or NULL; lam, tail, status (L,) out. */
INLINE void family_lanes(const int L, int count, const Family *f, int terms,
                         const double *coef, const double *coef_lo, const double *ceiling,
                         const ModalControl *ctl, double *work, double *lam, double *tail,
                         int *status) {
  const int k1 = f->k1, k2 = f->k2, m = k1 + k2, e1 = f->schur == 2;
  const int ke = e1 ? k1 : k2, ks = e1 ? k2 : k1;
  const double shift = ctl->shift;
  /* lane layout throughout: K - SHIFT's parts, the modal vectors z = (z1, z2), wl = (w1, w2)
     as the iteration leaves them, the pencil's vectors x, y (each (m, L)) */
  double *re = work, *ds = re + (size_t)L * ke, *z = ds + (size_t)L * ks;
  double *wl = z + (size_t)L * m, *x = wl + (size_t)L * m, *y = x + (size_t)L * m;
  double *rest = y + (size_t)L * m;  /* the iteration's workspace, then the quotient's */
  const double *lam_e = e1 ? f->lam1 : f->lam2, *lam_s = e1 ? f->lam2 : f->lam1;
  const int qe = e1 ? 0 : 1, qs = 1 - qe;  /* equations of the e and s blocks */
  const double *c0e = AT(coef, f->own0[qe]), *c2e = AT(coef, f->own2[qe]);
  const double *c0s = AT(coef, f->own0[qs]), *c2s = AT(coef, f->own2[qs]);
  double al[LANES], bl[LANES];
  for (int j = 0; j < ke; j++) {
    double *rj = AT(re, j);
    for (int w = 0; w < L; w++) rj[w] = 1.0 / (c0e[w] - c2e[w] * lam_e[j] - shift);
  }
  for (int j = 0; j < ks; j++) {
    double *dj = AT(ds, j);
    for (int w = 0; w < L; w++) dj[w] = c0s[w] - c2s[w] * lam_s[j] - shift;
  }
  for (int w = 0; w < L; w++) {
    al[w] = 2.0 * AT(coef, f->coupling[qe])[w];
    bl[w] = 2.0 * AT(coef, f->coupling[qs])[w];
    lam[w] = NAN;
    status[w] = NOT_CONVERGED;
  }
  /* the e block is omega1's (rows 0..k1) where e1, else omega2's (rows k1..m) */
  const int off_e = e1 ? 0 : k1, off_s = e1 ? k1 : 0;
  memset(z, 0, sizeof(double) * 2 * L * m);  /* a rejected lane's vectors stay defined */
  iterate_lanes(L, count, ke, ks, re, al, bl, ds, e1 ? f->g12 : f->g21, e1 ? f->g21 : f->g12,
                f->start + off_e, f->start + off_s, ceiling, ctl, rest, AT(z, off_e),
                AT(z, off_s), AT(wl, off_e), AT(wl, off_s), lam, status);
  int any_converged = 0;  /* the vectors serve converged lanes only (the others' tail: inf) */
  for (int w = 0; w < count; w++) {
    tail[w] = INFINITY;
    any_converged |= status[w] == CONVERGED;
  }
  if (!any_converged) return;
  /* x = (U1 z1, U2 z2), y = (left1^T w1, left2^T w2) */
  lanes_product(L, k1, f->u1, 0, z, x);
  lanes_product(L, k2, f->u2, 0, AT(z, k1), AT(x, k1));
  double last[LANES], other[LANES], c[LANES];
  for (int w = 0; w < L; w++) last[w] = other[w] = 0.0;
  for (int r = 0; r < f->tail_count; r++) {  /* resolution.tail_parts and tail_from_parts */
    for (int w = 0; w < L; w++) c[w] = 0.0;
    for (int j = 0; j < m; j++) {
      const double t = f->tail_rows[(size_t)r * m + j], *xj = AT(x, j);
      for (int w = 0; w < L; w++) c[w] += t * xj[w];
    }
    double *part = r < 4 ? last : other;
    for (int w = 0; w < L; w++) part[w] = nan_max(part[w], fabs(c[w]));
  }
  for (int w = 0; w < count; w++) {
    const double scale = nan_max(last[w], other[w]);
    if (status[w] != CONVERGED) continue;
    tail[w] = scale > 0.0 ? last[w] / scale : INFINITY;
    if (!isfinite(last[w]) || !isfinite(other[w])) status[w] = NOT_CONVERGED;
  }
  if (ctl->loose) return;
  lanes_product(L, k1, f->left1, 1, wl, y);
  lanes_product(L, k2, f->left2, 1, AT(wl, k1), AT(y, k1));
  double q[LANES];
  pencil_quotient(L, f, terms, coef, coef_lo, x, y, rest, q);
  for (int w = 0; w < count; w++) {
    if (status[w] != CONVERGED) continue;
    lam[w] = q[w];
    if (!(q[w] >= shift)) status[w] = NOT_CONVERGED;  /* a nan quotient is not an answer */
  }
}

/* Both families of `count` <= L points from i0 on (symmetric first, the antisymmetric one only
   shown to lie above (1 + close_rel) times it where it does): the coefficients into lane
   layout, then family_lanes twice. */
INLINE void points_lanes(const int L, int i0, int count, const Family *fam,
                         const ModalPoints *pts, const ModalControl *control,
                         const ModalControl *anti, double *work, ModalPointResults *out) {
  const int terms = pts->terms;
  double *coef = work, *coef_lo = coef + (size_t)L * terms, *rest = coef_lo + (size_t)L * terms;
  for (int w = 0; w < L; w++) {
    const size_t i = (size_t)(i0 + (w < count ? w : count - 1)) * terms;
    for (int t = 0; t < terms; t++) AT(coef, t)[w] = pts->coef[i + t];
    if (pts->coef_lo)
      for (int t = 0; t < terms; t++) AT(coef_lo, t)[w] = pts->coef_lo[i + t];
  }
  const double *lo = pts->coef_lo ? coef_lo : NULL;
  double lam[2][LANES], tail[2][LANES], ceiling[LANES];
  int status[2][LANES];
  family_lanes(L, count, &fam[0], terms, coef, lo, NULL, control, rest, lam[0], tail[0],
               status[0]);
  for (int w = 0; w < L; w++)  /* no ceiling (inf) where the symmetric family failed */
    ceiling[w] = w < count && status[0][w] == CONVERGED ? lam[0][w] * (1.0 + control->close_rel)
                                                        : INFINITY;
  family_lanes(L, count, &fam[1], terms, coef, lo, ceiling, anti, rest, lam[1], tail[1],
               status[1]);
  for (int w = 0; w < count; w++)
    for (int q = 0; q < 2; q++) {
      const size_t at = 2 * (size_t)(i0 + w) + q;
      out->lam[at] = lam[q][w];
      out->tail[at] = tail[q][w];
      out->status[at] = status[q][w];
    }
}

/* points_lanes on LANES lanes and on one, each compiled on its own (with the clones): inlined
   together into modal_points the one-lane code was compiled ~6 % slower. */
CLONES static void points_group(int i0, int count, const Family *fam, const ModalPoints *pts,
                                const ModalControl *control, const ModalControl *anti,
                                double *work, ModalPointResults *out) {
  points_lanes(LANES, i0, count, fam, pts, control, anti, work, out);
}

CLONES static void points_one(int i0, const Family *fam, const ModalPoints *pts,
                              const ModalControl *control, const ModalControl *anti,
                              double *work, ModalPointResults *out) {
  points_lanes(1, i0, 1, fam, pts, control, anti, work, out);
}

/* Both families at P points (_modal_kernel.h): LANES at a time; a last group of at most
   control->few points one lane each, a larger one as one group of LANES lanes. */
CLONES int modal_points(const Family *fam, const ModalPoints *pts, const ModalControl *control,
                        ModalPointResults *out) {
  if (!fam) return -1;
  if (!pts || pts->P < 0 || pts->terms < 1 || (pts->P && !pts->coef)) return -2;
  if (!control || control->first < 1 || control->max_steps < control->first || control->few < 0)
    return -3;
  if (!out || (pts->P && (!out->lam || !out->tail || !out->status))) return -4;
  const size_t T = (size_t)pts->terms;
  size_t need = 0;  /* per lane, the larger family's */
  for (int q = 0; q < 2; q++) {
    const size_t k1 = fam[q].k1, k2 = fam[q].k2, m = k1 + k2;
    const size_t ks = fam[q].schur == 2 ? k2 : k1, ke = m - ks;
    /* family_lanes' parts and vectors 5 m, then the iteration's or the quotient's */
    const size_t iteration = 2 * ks * ks + 4 * ke + 5 * ks;
    const size_t family = 5 * m + (iteration > 2 * T ? iteration : 2 * T);
    if (family > need) need = family;
  }
  /* LANES lanes where a group of LANES runs, else one (a scalar call's workspace stays small);
     the coefficients and their low parts first, 2 T */
  const size_t lanes = pts->P >= LANES || pts->P > control->few ? LANES : 1;
  double *work = workspace(lanes * (2 * T + need));
  if (!work) return 1;
  ModalControl anti = *control;  /* the antisymmetric family may stop early: an earlier test */
  if (anti.first > 4) anti.first = 4;
  const int P = pts->P;
  int i0 = 0;
  for (; P - i0 >= LANES || P - i0 > control->few; i0 += LANES)  /* few >= 0: P - i0 > 0 */
    points_group(i0, P - i0 < LANES ? P - i0 : LANES, fam, pts, control, &anti, work, out);
  for (; i0 < P; i0++)
    points_one(i0, fam, pts, control, &anti, work, out);
  release(work);
  return 0;
}


/* The module stub: the build is an importable extension (so that setuptools builds it on every
   platform); the kernel itself is called through ctypes. */

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_modal_kernel",
    "C kernel of the batched engine (loaded with ctypes).", -1, NULL, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit__modal_kernel(void) { return PyModule_Create(&module); }
