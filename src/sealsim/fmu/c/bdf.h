/* The BDF integrator of bdf.c (a port of sealsim.ode.bdf) for up to BDF_MAXN states. */
#ifndef SEALSIM_BDF_H
#define SEALSIM_BDF_H

#include <math.h>
#include <string.h>

#ifndef BDF_MAXN
#define BDF_MAXN 16
#endif
#define BDF_MAX_ORDER 5
#define BDF_OK 0
#define BDF_TOO_SMALL_STEP (-1)

typedef struct {
    void *ctx;
    void (*fun)(void *ctx, double t, const double *y, double *dy);
    /* J[i * BDF_MAXN + j] = df_i/dy_j at (t, y); f = fun(t, y), which the integrator has
     * already evaluated (sealsim.ode.bdf's JAC) */
    void (*jac)(void *ctx, double t, const double *y, const double *f, double *J);
    double (*event)(void *ctx, double t, const double *y);
    /* the growth rate (>= 0) of a Jacobian J, which limits the step (sealsim.ode.bdf); NULL:
     * none */
    double (*growth)(void *ctx, double t, const double *y, const double *J);
    /* renews the columns of J that growth reads at (t, y), f = fun(t, y), and returns the
     * growth rate (sealsim.ode.bdf's RENEW); NULL: the whole Jacobian is renewed */
    double (*renew)(void *ctx, double t, const double *y, const double *f, double *J);
} BdfProblem;

typedef struct {
    int n, order, n_equal, lu_ok, limited;
    long nfev, njev, nlu, nsteps, nrenew;
    double t, t_old, h_abs, rtol, max_step, newton_tol, t_bound, growth;
    double atol[BDF_MAXN];
    double D[(BDF_MAX_ORDER + 3) * BDF_MAXN];
    double J[BDF_MAXN * BDF_MAXN], LU[BDF_MAXN * BDF_MAXN];
    int piv[BDF_MAXN];
    double y_pred[BDF_MAXN], psi[BDF_MAXN], y_new[BDF_MAXN], d[BDF_MAXN], f[BDF_MAXN];
    double dy[BDF_MAXN], scale[BDF_MAXN], err[BDF_MAXN];
    double f_pred[BDF_MAXN];        /* fun at the predicted state: where a new Jacobian starts */
} Bdf;

void bdf_init(Bdf *b, int n, double rtol, const double *atol, double max_step);
/* start (or restart) at (t0, y0) towards t_bound: order 1, scipy's initial step */
void bdf_start(Bdf *b, double t0, const double *y0, double t_bound, const BdfProblem *p);
/* one accepted step: BDF_OK (state b->y_new at b->t) or BDF_TOO_SMALL_STEP */
int bdf_step(Bdf *b, const BdfProblem *p);
/* the solution at t within the last step */
void bdf_dense(const Bdf *b, double t, double *out);
/* root of the event function within the last step (Brent, 4 eps) */
double bdf_locate(Bdf *b, const BdfProblem *p, double g_old, double g_new, double *y_tmp);

#endif
