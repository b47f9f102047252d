/* The variable-order BDF integrator of sealsim.ode.bdf (scipy's BDF: quasi-constant step
 * size, backward differences, NDF coefficients, simplified Newton with a kept Jacobian) and
 * its Brent event location, in C: the integrator inside the co-simulation of an FMU.
 *
 * A line-by-line port of src/sealsim/ode/bdf.py (same constants, same step and order
 * control, same dense output), without the quadrature states (every state here is dynamic);
 * the FMU tests run both on the cylinder and compare the results.  Sizes are fixed at
 * compile time (BDF_MAXN states), so the solver state is a plain struct that an FMU state
 * copy (fmi2GetFMUstate) takes along.
 */
#include "bdf.h"

#define BDF_NEWTON_MAXITER 4
#define BDF_MIN_FACTOR 0.2
#define BDF_MAX_FACTOR 10.0
#define BDF_GROWTH_LIMIT 0.5
#define BDF_EPS 2.220446049250313e-16

/* kappa, gamma = cumsum(1/k), alpha = (1 - kappa) gamma, error constants kappa gamma +
 * 1/(k + 1) (sealsim.ode.bdf's KAPPA, GAMMA, ALPHA, ERROR_CONST): constant expressions, folded
 * by the compiler with the rounding of each operation, so the same numbers as the sums
 * computed at run time (they were, 25 times per step) */
#define KAPPA1 (-0.1850)
#define KAPPA2 (-1.0 / 9.0)
#define KAPPA3 (-0.0823)
#define KAPPA4 (-0.0415)
#define GAMMA1 (0.0 + 1.0 / 1)
#define GAMMA2 (GAMMA1 + 1.0 / 2)
#define GAMMA3 (GAMMA2 + 1.0 / 3)
#define GAMMA4 (GAMMA3 + 1.0 / 4)
#define GAMMA5 (GAMMA4 + 1.0 / 5)
static const double GAMMA[6] = {0.0, GAMMA1, GAMMA2, GAMMA3, GAMMA4, GAMMA5};
static const double ALPHA[6] = {
    (1.0 - 0.0) * 0.0, (1.0 - KAPPA1) * GAMMA1, (1.0 - KAPPA2) * GAMMA2,
    (1.0 - KAPPA3) * GAMMA3, (1.0 - KAPPA4) * GAMMA4, (1.0 - 0.0) * GAMMA5};
static const double ERROR_CONST[6] = {
    0.0 * 0.0 + 1.0 / 1, KAPPA1 * GAMMA1 + 1.0 / 2, KAPPA2 * GAMMA2 + 1.0 / 3,
    KAPPA3 * GAMMA3 + 1.0 / 4, KAPPA4 * GAMMA4 + 1.0 / 5, 0.0 * GAMMA5 + 1.0 / 6};

#define D_(b, k, i) ((b)->D[(k) * BDF_MAXN + (i)])

static double rms(const double *x, const double *scale, int m) {
    double acc = 0.0;
    for (int i = 0; i < m; i++) {
        double q = x[i] / scale[i];
        acc += q * q;
    }
    return sqrt(acc) / sqrt((double)m);
}

/* LU with partial pivoting (sealsim.ode.bdf.lu_factor), row-major n x n with stride BDF_MAXN */
static int lu_factor(double *a, int *piv, int n) {
    for (int k = 0; k < n; k++) {
        int p = k;
        double big = fabs(a[k * BDF_MAXN + k]);
        for (int i = k + 1; i < n; i++) {
            if (fabs(a[i * BDF_MAXN + k]) > big) {
                big = fabs(a[i * BDF_MAXN + k]);
                p = i;
            }
        }
        piv[k] = p;
        if (big == 0.0) return 0;
        if (p != k) {
            for (int j = 0; j < n; j++) {
                double tmp = a[k * BDF_MAXN + j];
                a[k * BDF_MAXN + j] = a[p * BDF_MAXN + j];
                a[p * BDF_MAXN + j] = tmp;
            }
        }
        double inv = 1.0 / a[k * BDF_MAXN + k];
        for (int i = k + 1; i < n; i++) {
            a[i * BDF_MAXN + k] *= inv;
            double m = a[i * BDF_MAXN + k];
            if (m != 0.0) {
                for (int j = k + 1; j < n; j++) a[i * BDF_MAXN + j] -= m * a[k * BDF_MAXN + j];
            }
        }
    }
    return 1;
}

static void lu_solve(const double *lu, const int *piv, double *b, int n) {
    for (int k = 0; k < n; k++) {
        int p = piv[k];
        if (p != k) {
            double tmp = b[k];
            b[k] = b[p];
            b[p] = tmp;
        }
    }
    for (int i = 0; i < n; i++) {
        double acc = b[i];
        for (int j = 0; j < i; j++) acc -= lu[i * BDF_MAXN + j] * b[j];
        b[i] = acc;
    }
    for (int i = n - 1; i >= 0; i--) {
        double acc = b[i];
        for (int j = i + 1; j < n; j++) acc -= lu[i * BDF_MAXN + j] * b[j];
        b[i] = acc / lu[i * BDF_MAXN + i];
    }
}

/* D[:order+1] = (R(factor) R(1))^T D[:order+1] (scipy's change_D) */
static void change_differences(Bdf *b, int order, double factor) {
    double r[6][6], u[6][6], ru[6][6], col[6];
    int m = order + 1;
    for (int j = 0; j < m; j++) {
        r[0][j] = 1.0;
        u[0][j] = 1.0;
    }
    for (int i = 1; i < m; i++) {
        r[i][0] = 0.0;
        u[i][0] = 0.0;
        for (int j = 1; j < m; j++) {
            r[i][j] = r[i - 1][j] * ((i - 1 - factor * j) / i);
            u[i][j] = u[i - 1][j] * ((i - 1 - 1.0 * j) / i);
        }
    }
    for (int i = 0; i < m; i++) {
        for (int j = 0; j < m; j++) {
            double acc = 0.0;
            for (int k = 0; k < m; k++) acc += r[i][k] * u[k][j];
            ru[i][j] = acc;
        }
    }
    for (int c = 0; c < b->n; c++) {
        for (int i = 0; i < m; i++) col[i] = D_(b, i, c);
        for (int i = 0; i < m; i++) {
            double acc = 0.0;
            for (int k = 0; k < m; k++) acc += ru[k][i] * col[k];
            D_(b, i, c) = acc;
        }
    }
}

void bdf_dense(const Bdf *b, double t, double *out) {
    double p = 1.0;
    for (int i = 0; i < b->n; i++) out[i] = b->D[i];
    for (int k = 0; k < b->order; k++) {
        p *= (t - (b->t - b->h_abs * k)) / (b->h_abs * (1 + k));
        for (int i = 0; i < b->n; i++) out[i] += b->D[(k + 1) * BDF_MAXN + i] * p;
    }
}

void bdf_init(Bdf *b, int n, double rtol, const double *atol, double max_step) {
    memset(b, 0, sizeof *b);
    b->n = n;
    b->rtol = rtol;
    b->max_step = max_step;
    b->newton_tol = fmax(10.0 * BDF_EPS / rtol, fmin(0.03, sqrt(rtol)));
    for (int i = 0; i < n; i++) b->atol[i] = atol[i];
}

/* the Jacobian at (t, y), f = fun(t, y), and its growth rate */
static void jacobian(Bdf *b, const BdfProblem *p, double t, const double *y, const double *f) {
    p->jac(p->ctx, t, y, f, b->J);
    b->njev++;
    b->growth = p->growth ? p->growth(p->ctx, t, y, b->J) : 0.0;
    b->limited = 0;
}

/* the growth rate renewed at (t, y), f = fun(t, y): the columns it reads (p->renew) or the
 * whole Jacobian */
static void renew_growth(Bdf *b, const BdfProblem *p, double t, const double *y,
                         const double *f) {
    if (!p->renew) {
        jacobian(b, p, t, y, f);
        return;
    }
    b->growth = p->renew(p->ctx, t, y, f, b->J);
    b->nrenew++;
    b->limited = 0;
}

void bdf_start(Bdf *b, double t0, const double *y0, double t_bound, const BdfProblem *p) {
    int n = b->n;
    double *f0 = b->f, *y1 = b->dy, *f1 = b->d, *scale = b->scale;
    double h_abs;
    b->t = t0;
    b->t_old = t0;
    b->t_bound = t_bound;
    p->fun(p->ctx, t0, y0, f0);
    b->nfev++;
    double interval = fabs(t_bound - t0);
    if (interval == 0.0) {
        h_abs = 0.0;
    } else {
        for (int i = 0; i < n; i++) scale[i] = b->atol[i] + fabs(y0[i]) * b->rtol;
        double d0 = rms(y0, scale, n), d1 = rms(f0, scale, n);
        double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
        h0 = fmin(h0, interval);
        for (int i = 0; i < n; i++) y1[i] = y0[i] + h0 * f0[i];
        p->fun(p->ctx, t0 + h0, y1, f1);
        b->nfev++;
        for (int i = 0; i < n; i++) y1[i] = f1[i] - f0[i];
        double d2 = rms(y1, scale, n) / h0, h1;
        if (d1 <= 1e-15 && d2 <= 1e-15) h1 = fmax(1e-6, h0 * 1e-3);
        else h1 = sqrt(0.01 / fmax(d1, d2));
        h_abs = fmin(fmin(100.0 * h0, h1), fmin(interval, b->max_step));
    }
    b->h_abs = h_abs;
    for (int i = 0; i < n; i++) {
        b->D[i] = y0[i];
        b->D[BDF_MAXN + i] = f0[i] * h_abs;
    }
    jacobian(b, p, t0, y0, f0);
    b->order = 1;
    b->n_equal = 0;
    b->lu_ok = 0;
}

/* simplified Newton iteration of the BDF system: 1 when converged; iterations in *iters */
static int newton(Bdf *b, const BdfProblem *p, double t_new, double c, int *iters) {
    int n = b->n;
    double dy_norm_old = -1.0;
    for (int i = 0; i < n; i++) {
        b->y_new[i] = b->y_pred[i];
        b->d[i] = 0.0;
    }
    *iters = 0;
    for (int k = 0; k < BDF_NEWTON_MAXITER; k++) {
        *iters = k + 1;
        p->fun(p->ctx, t_new, b->y_new, b->f);
        b->nfev++;
        if (k == 0) {                   /* f(y_pred): what a new Jacobian at y_pred starts from */
            for (int i = 0; i < n; i++) b->f_pred[i] = b->f[i];
        }
        int finite = 1;
        for (int i = 0; i < n; i++) {
            if (!isfinite(b->f[i])) finite = 0;
        }
        if (!finite) return 0;
        for (int i = 0; i < n; i++) b->dy[i] = c * b->f[i] - b->psi[i] - b->d[i];
        lu_solve(b->LU, b->piv, b->dy, n);
        double dy_norm = rms(b->dy, b->scale, n), rate = -1.0;
        if (dy_norm_old >= 0.0) rate = dy_norm / dy_norm_old;
        if (rate >= 0.0 &&
            (rate >= 1.0 || pow(rate, BDF_NEWTON_MAXITER - k) / (1.0 - rate) * dy_norm >
                                b->newton_tol))
            return 0;
        for (int i = 0; i < n; i++) {
            b->y_new[i] += b->dy[i];
            b->d[i] += b->dy[i];
        }
        if (dy_norm == 0.0 || (rate >= 0.0 && rate / (1.0 - rate) * dy_norm < b->newton_tol))
            return 1;
        dy_norm_old = dy_norm;
    }
    return 0;
}

static double order_factor(double error_norm, int power) {
    return error_norm == 0.0 ? INFINITY : pow(error_norm, -1.0 / power);
}

int bdf_step(Bdf *b, const BdfProblem *p) {
    int n = b->n, order = b->order, n_iter = 0;
    double t = b->t, h_abs = b->h_abs, error_norm = 0.0, safety = 0.0;
    double min_step = 10.0 * fabs(nextafter(t, INFINITY) - t);
    int current_jac = 0, renewed = 0;
    if (h_abs > b->max_step) {
        change_differences(b, order, b->max_step / h_abs);
        h_abs = b->max_step;
        b->n_equal = 0;
    } else if (h_abs < min_step) {
        change_differences(b, order, min_step / h_abs);
        h_abs = min_step;
        b->n_equal = 0;
    }
    /* the growth limit c lambda+ <= BDF_GROWTH_LIMIT (sealsim.ode.bdf); a Jacobian limits one
     * step: where the limit would bind again, lambda+ is renewed at the current state first */
    if (b->growth > 0.0) {
        double h_growth = BDF_GROWTH_LIMIT * ALPHA[order] / b->growth;
        if (h_abs > h_growth && b->limited) {
            p->fun(p->ctx, t, b->D, b->f);
            b->nfev++;
            renew_growth(b, p, t, b->D, b->f);
            b->lu_ok = 0;
            h_growth = b->growth > 0.0 ? BDF_GROWTH_LIMIT * ALPHA[order] / b->growth
                                       : INFINITY;
        }
        if (h_abs > h_growth && h_growth >= min_step) {
            change_differences(b, order, h_growth / h_abs);
            h_abs = h_growth;
            b->n_equal = 0;
            b->lu_ok = 0;
            b->limited = 1;
        }
    }
    for (;;) {
        if (h_abs < min_step) return BDF_TOO_SMALL_STEP;
        double t_new = t + h_abs;
        if (t_new - b->t_bound > 0.0) {
            t_new = b->t_bound;
            change_differences(b, order, fabs(t_new - t) / h_abs);
            b->n_equal = 0;
            b->lu_ok = 0;
        }
        double h = t_new - t;
        h_abs = fabs(h);
        for (int i = 0; i < n; i++) {
            double acc = 0.0;
            for (int k = 0; k <= order; k++) acc += D_(b, k, i);
            b->y_pred[i] = acc;
            b->scale[i] = b->atol[i] + b->rtol * fabs(acc);
            acc = 0.0;
            for (int k = 1; k <= order; k++) acc += D_(b, k, i) * GAMMA[k];
            b->psi[i] = acc / ALPHA[order];
        }
        double c = h / ALPHA[order];
        int converged = 0;
        while (!converged) {
            if (!b->lu_ok) {
                for (int i = 0; i < n; i++) {
                    for (int j = 0; j < n; j++)
                        b->LU[i * BDF_MAXN + j] = -c * b->J[i * BDF_MAXN + j];
                    b->LU[i * BDF_MAXN + i] += 1.0;
                }
                lu_factor(b->LU, b->piv, n);
                b->nlu++;
                b->lu_ok = 1;
            }
            converged = newton(b, p, t_new, c, &n_iter);
            if (!converged) {
                if (current_jac) break;
                b->lu_ok = 0;
                if (p->renew && b->growth > 0.0 && !renewed) {
                    /* a growing state stalls the iteration: its columns first, the step
                     * within the growth limit of the renewed lambda+ (sealsim.ode.bdf) */
                    renew_growth(b, p, t_new, b->y_pred, b->f_pred);
                    renewed = 1;
                    if (c * b->growth > BDF_GROWTH_LIMIT
                        && BDF_GROWTH_LIMIT * ALPHA[order] / b->growth >= min_step)
                        break;
                } else {
                    jacobian(b, p, t_new, b->y_pred, b->f_pred);
                    current_jac = 1;
                }
            }
        }
        if (!converged) {
            double factor = 0.5;
            if (p->renew && renewed && c * b->growth > BDF_GROWTH_LIMIT) {
                factor = fmin(0.5, BDF_GROWTH_LIMIT * ALPHA[order] / b->growth / h_abs);
                b->limited = 1;
            }
            h_abs *= factor;
            change_differences(b, order, factor);
            b->n_equal = 0;
            b->lu_ok = 0;
            continue;
        }
        safety = 0.9 * (2 * BDF_NEWTON_MAXITER + 1) / (2 * BDF_NEWTON_MAXITER + n_iter);
        for (int i = 0; i < n; i++) {
            b->scale[i] = b->atol[i] + b->rtol * fabs(b->y_new[i]);
            b->err[i] = ERROR_CONST[order] * b->d[i];
        }
        error_norm = rms(b->err, b->scale, n);
        if (error_norm > 1.0) {
            double factor = fmax(BDF_MIN_FACTOR, safety * pow(error_norm, -1.0 / (order + 1)));
            h_abs *= factor;
            change_differences(b, order, factor);
            b->n_equal = 0;
        } else {
            b->t_old = t;
            b->t = t_new;
            break;
        }
    }
    b->n_equal++;
    b->nsteps++;
    b->h_abs = h_abs;
    for (int i = 0; i < n; i++) {
        D_(b, order + 2, i) = b->d[i] - D_(b, order + 1, i);
        D_(b, order + 1, i) = b->d[i];
    }
    for (int k = order; k >= 0; k--) {
        for (int i = 0; i < n; i++) D_(b, k, i) += D_(b, k + 1, i);
    }
    if (b->n_equal < order + 1) return BDF_OK;
    double error_m = INFINITY, error_p = INFINITY;
    if (order > 1) {
        for (int i = 0; i < n; i++) b->err[i] = ERROR_CONST[order - 1] * D_(b, order, i);
        error_m = rms(b->err, b->scale, n);
    }
    if (order < BDF_MAX_ORDER) {
        for (int i = 0; i < n; i++) b->err[i] = ERROR_CONST[order + 1] * D_(b, order + 2, i);
        error_p = rms(b->err, b->scale, n);
    }
    double f_m = order_factor(error_m, order), f_0 = order_factor(error_norm, order + 1);
    double f_p = order_factor(error_p, order + 2), best = f_0;
    int delta = 0;
    if (f_m > best) {
        best = f_m;
        delta = -1;
    }
    if (f_p > best) {
        best = f_p;
        delta = 1;
    }
    order += delta;
    b->order = order;
    double factor = fmin(BDF_MAX_FACTOR, safety * best);
    b->h_abs = h_abs * factor;
    change_differences(b, order, factor);
    b->n_equal = 0;
    b->lu_ok = 0;
    return BDF_OK;
}

double bdf_locate(Bdf *b, const BdfProblem *p, double g_old, double g_new, double *y_tmp) {
    const double xtol = 4.0 * BDF_EPS, rtol = 4.0 * BDF_EPS;
    double xpre = b->t_old, xcur = b->t, fpre = g_old, fcur = g_new;
    double xblk = 0.0, fblk = 0.0, spre = 0.0, scur = 0.0;
    if (fpre == 0.0) return xpre;
    if (fcur == 0.0) return xcur;
    for (int it = 0; it < 100; it++) {
        if (fpre != 0.0 && fcur != 0.0 && ((fpre < 0.0) != (fcur < 0.0))) {
            xblk = xpre;
            fblk = fpre;
            spre = scur = xcur - xpre;
        }
        if (fabs(fblk) < fabs(fcur)) {
            xpre = xcur;
            xcur = xblk;
            xblk = xpre;
            fpre = fcur;
            fcur = fblk;
            fblk = fpre;
        }
        double delta = (xtol + rtol * fabs(xcur)) / 2.0, sbis = (xblk - xcur) / 2.0;
        if (fcur == 0.0 || fabs(sbis) < delta) return xcur;
        if (fabs(spre) > delta && fabs(fcur) < fabs(fpre)) {
            double stry;
            if (xpre == xblk) {
                stry = -fcur * (xcur - xpre) / (fcur - fpre);
            } else {
                double dpre = (fpre - fcur) / (xpre - xcur), dblk = (fblk - fcur) / (xblk - xcur);
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre));
            }
            if (2.0 * fabs(stry) < fmin(fabs(spre), 3.0 * fabs(sbis) - delta)) {
                spre = scur;
                scur = stry;
            } else {
                spre = sbis;
                scur = sbis;
            }
        } else {
            spre = sbis;
            scur = sbis;
        }
        xpre = xcur;
        fpre = fcur;
        if (fabs(scur) > delta) xcur += scur;
        else xcur += sbis > 0.0 ? delta : -delta;
        bdf_dense(b, xcur, y_tmp);
        fcur = p->event(p->ctx, xcur, y_tmp);
    }
    return xcur;
}
