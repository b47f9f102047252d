/* C1 piecewise-cubic Hermite interpolation on a rectilinear 2-D grid.
 *
 * Per cell [x0_i, x0_i+1] x [x1_j, x1_j+1] the tensor product of the cubic Hermite basis
 * h00(t) = 2t^3 - 3t^2 + 1, h10(t) = t^3 - 2t^2 + t, h01(t) = -2t^3 + 3t^2, h11(t) = t^3 - t^2
 * weights the node values, first derivatives (times the cell size) and mixed derivatives:
 * the scheme of sealsim.structure.maps.HermiteGrid (Fritsch & Carlson 1980 slopes for
 * sampled data).  The caller clips the point to the grid; the cell search is the index
 * of the last node <= x, limited to the last cell. */
#include "sealsim_fmu.h"

static int hermite_cell(const double *x, int n, double v) {
    int lo = 0, hi = n;             /* first index with x[i] > v (bisect right) */
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (v < x[mid]) hi = mid; else lo = mid + 1;
    }
    int i = lo - 1;
    if (i < 0) i = 0;
    if (i > n - 2) i = n - 2;
    return i;
}

static void hermite_basis(double t, double h, double *value_weight, double *slope_weight) {
    double t2 = t * t, t3 = t2 * t;
    value_weight[0] = 2.0 * t3 - 3.0 * t2 + 1.0;
    slope_weight[0] = (t3 - 2.0 * t2 + t) * h;
    value_weight[1] = -2.0 * t3 + 3.0 * t2;
    slope_weight[1] = (t3 - t2) * h;
}

void hermite_evaluate(const HermiteTable *t, double a, double b, double *out) {
    int i = hermite_cell(t->x0, t->n0, a);
    int j = hermite_cell(t->x1, t->n1, b);
    double h0 = t->x0[i + 1] - t->x0[i], h1 = t->x1[j + 1] - t->x1[j];
    double v0[2], s0[2], v1[2], s1[2];
    hermite_basis((a - t->x0[i]) / h0, h0, v0, s0);
    hermite_basis((b - t->x1[j]) / h1, h1, v1, s1);
    int nv = t->nvars;
    for (int k = 0; k < nv; k++) out[k] = 0.0;
    for (int ci = 0; ci < 2; ci++) {
        for (int cj = 0; cj < 2; cj++) {
            const double *node = t->data + ((size_t)(i + ci) * t->n1 + (j + cj)) * 4 * nv;
            double w_value = v0[ci] * v1[cj], w_d0 = s0[ci] * v1[cj];
            double w_d1 = v0[ci] * s1[cj], w_d01 = s0[ci] * s1[cj];
            for (int k = 0; k < nv; k++) {
                out[k] += w_value * node[k] + w_d0 * node[nv + k] + w_d1 * node[2 * nv + k] +
                          w_d01 * node[3 * nv + k];
            }
        }
    }
}
