/* The C contract of the collocation engine for Eq. inst1 (modal form), spectral_rod.

   Entry points, each documented below in the manner of LAPACK (argument, in/out, dimension,
   meaning; a return value INFO):

     modal_lowest      the lowest eigenpair of K nearest above SHIFT and its vectors at P
                       points of one family (LANES points side by side; for a family on its
                       own and for the numpy engine's comparisons);
     modal_points      both families at P points, LANES side by side (a few, one lane each),
                       with the mode's tail and the pencil's two-sided Rayleigh quotient: the
                       engine of every call shape;
     pencil_terms_dd   the pencil's bilinear forms y_e^T M_t x_f in double-double;
     modal_abi_version, modal_lanes, modal_isa, modal_struct_size: what the loader checks
                       (spectral_rod/rod/collocation/modal_kernel.py refuses a build whose ABI
                       version or struct sizes differ from its own and runs the numpy engine).

   Every array is row-major (C order), one row a point, and must not alias an output.
   INFO (the return value of every solver entry point):
       = 0   success;
       < 0   if INFO = -i, the i-th argument (counted from 1) had an illegal value (a null
             pointer or a negative size); nothing was written;
       = 1   the workspace could not be allocated; nothing was solved.
   A point's own outcome is not an INFO but its status (MODAL_* below).

   Arguments travel as the structs below, so that a reviewer can check each field against
   this header and the ctypes mirror (modal_kernel.py), whose sizes the loader compares with
   modal_struct_size. Change MODAL_KERNEL_ABI whenever a struct or a signature changes. */

#ifndef SPECTRAL_ROD_MODAL_KERNEL_H
#define SPECTRAL_ROD_MODAL_KERNEL_H

#include <stddef.h>

#define MODAL_KERNEL_ABI 3

/* Status of a point (modal_kernel.py's NOT_CONVERGED, CONVERGED, ABOVE, REJECTED). */
enum {
  MODAL_NOT_CONVERGED = 0, /* max_steps reached, or the quotient is below shift or nan */
  MODAL_CONVERGED = 1,     /* first-order error bound <= rtol |lambda| and lambda >= shift */
  MODAL_ABOVE = 2,         /* shown above the ceiling: lambda and the vectors approximate */
  MODAL_REJECTED = -1      /* the unpivoted LU failed its probe test: solve it elsewhere */
};

/* ModalControl: the iteration's settings (spectral_rod/rod/collocation/tuning.py derives them
   from tol; solver_settings).
     shift         in  SHIFT, below every physical eigenvalue (0.95 pi^2).
     rtol          in  accepted first-order error bound of lambda, relative.
     backward_tol  in  the probe test's bound on the LU's backward error (BACKWARD_TOL).
     close_rel     in  modal_points only: the antisymmetric family stops once shown above
                       (1 + close_rel) times the symmetric lambda.
     first         in  the step of the first convergence test (then every 2 steps), >= 1.
     max_steps     in  the step cap, >= first.
     loose         in  modal_points only: 1 = lambda is the modal quotient w^T K z / w^T z,
                       0 = the pencil's two-sided quotient y^T A x / y^T B x.
     few           in  modal_points only, >= 0: a last group of at most `few` points (fewer
                       than LANES) is solved one lane at a time, a larger one as a group of
                       LANES lanes (tuning.few_points_limit). */
typedef struct {
  double shift, rtol, backward_tol, close_rel;
  int first, max_steps, loose, few;
} ModalControl;

/* ModalBatch: K - SHIFT at P points of one family in its Schur blocks (eigensolver.ModalParts).
     P        in  number of points, >= 0.
     ke, ks   in  sizes of the eliminated and the Schur block, >= 1.
     r_e      in  (P, ke)  1 / (D_e - shift).
     a, b     in  (P,)     coupling factors of the e and the s block.
     d_s      in  (P, ks)  D_s - shift.
     g_es     in  (ke, ks) coupling G_es;  g_se in (ks, ke) coupling G_se.
     start_e  in  (ke,)    the unit start vector's e block;  start_s in (ks,) its s block.
     ceiling  in  (P,) or NULL: a point whose lambda is shown above it stops, status ABOVE. */
typedef struct {
  int P, ke, ks;
  const double *r_e, *a, *b, *d_s, *g_es, *g_se, *start_e, *start_s, *ceiling;
} ModalBatch;

/* ModalEigenpairs: modal_lowest's results per point.
     lam     out  (P,)     the two-sided quotient w^T K z / w^T z.
     x_e     out  (P, ke)  unit right vector z, e block;  x_s out (P, ks) its s block.
     y_e     out  (P, ke)  unit left vector w, e block;   y_s out (P, ks) its s block.
     status  out  (P,)     MODAL_*; lam and the vectors are undefined where REJECTED. */
typedef struct {
  double *lam, *x_e, *x_s, *y_e, *y_s;
  int *status;
} ModalEigenpairs;

/* modal_lowest(batch, control, out) -> INFO.  Arguments: 1 batch, 2 control, 3 out. */
int modal_lowest(const ModalBatch *batch, const ModalControl *control, ModalEigenpairs *out);

/* Family: one mode family at one degree (eigensolver.ModalFamily and its pencil's terms;
   eigensolver.kernel_families fills it; every pointer must stay valid during the call).
     k1, k2          sizes of the omega1 and omega2 blocks;  schur: the Schur block, 1 or 2.
     own2, own0      per equation, indices into coef of its 2nd- and 0th-order own terms.
     coupling        per equation, the index of its 1st-order coupling term.
     lam1, lam2      (k1,), (k2,) eigenvalues of the uncoupled operators.
     g12, g21        (k1, k2), (k2, k1) modal couplings.
     u1, u2          (k1, k1), (k2, k2): the pencil's right vector c_i = U_i z_i.
     left1, left2    (k1, k1), (k2, k2): its left vector y_i^T = w_i^T left_i.
     start           (k1 + k2,) unit start vector.
     tail_count      rows of tail_rows (>= 5); the first 4 give the tail.
     tail_rows       (tail_count, k1 + k2) Chebyshev coefficients of the mode.
     term_shape      (terms, 5) per term of INST1 as for pencil_terms_dd.
     term_mats       the terms' matrices, concatenated.
     mass            (terms,) 1 for a term of B, else 0. */
typedef struct {
  int k1, k2, schur;
  int own2[2], own0[2], coupling[2];
  const double *lam1, *lam2;
  const double *g12, *g21;
  const double *u1, *u2;
  const double *left1, *left2;
  const double *start;
  int tail_count;
  const double *tail_rows;
  const int *term_shape;
  const double *term_mats;
  const int *mass;
} Family;

/* ModalPoints: P points given by their INST1 coefficients.
     P        in  number of points, >= 0;  terms in: coefficients per point, >= 1.
     coef     in  (P, terms) the coefficients (double part).
     coef_lo  in  (P, terms) or NULL: their low parts; given, the pencil's quotient is summed
                  in double-double (|Omega| > LONG_TWIST at tight tol). */
typedef struct {
  int P, terms;
  const double *coef, *coef_lo;
} ModalPoints;

/* ModalPointResults: per point and family (symmetric first).
     lam     out  (P, 2)  lambda = pi^2 p: the pencil's quotient, or the modal one if loose.
     tail    out  (P, 2)  the mode's Chebyshev tail (inf where not converged or above).
     status  out  (P, 2)  MODAL_*. */
typedef struct {
  double *lam, *tail;
  int *status;
} ModalPointResults;

/* modal_points(families, points, control, out) -> INFO.  families: in, (2,) symmetric then
   antisymmetric at one degree.  Arguments: 1 families, 2 points, 3 control, 4 out. */
int modal_points(const Family *families, const ModalPoints *points, const ModalControl *control,
                 ModalPointResults *out);

/* PencilForms: the pencil's term blocks and P pairs of vectors.
     P      in  number of points, >= 0;  m: vector length;  T: number of terms, >= 1.
     shape  in  (T, 5): per term (row offset, rows, column offset, columns, offset in mats).
     mats   in  the terms' matrices, row-major, concatenated.
     x, y   in  (P, m) right and left vectors.
     hi     out (P, T) the forms' high parts;  lo out (P, T) their low parts. */
typedef struct {
  int P, m, T;
  const int *shape;
  const double *mats, *x, *y;
  double *hi, *lo;
} PencilForms;

/* pencil_terms_dd(forms) -> INFO.  Argument: 1 forms. */
int pencil_terms_dd(PencilForms *forms);

/* MODAL_KERNEL_ABI of the build. */
int modal_abi_version(void);
/* LANES, the points a batch iterates side by side. */
int modal_lanes(void);
/* The instruction-set variant the loader picked ("x86-64-v4", "x86-64-v3", "default"), or
   "portable" where the build has a single variant. */
const char *modal_isa(void);
/* sizeof of struct `which`: 0 ModalControl, 1 ModalBatch, 2 ModalEigenpairs, 3 Family,
   4 ModalPoints, 5 ModalPointResults, 6 PencilForms; 0 for any other. */
size_t modal_struct_size(int which);

#endif
