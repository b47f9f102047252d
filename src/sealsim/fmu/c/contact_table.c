/* A seal's steady friction table from its own contact, and the Theta law's level on it.
 *
 * contact_table_point evaluates the interpolant of the numba kernel of the same name in
 * sealsim.friction.contact_table: the C1 tensor-product cubic Hermite interpolant over
 * (temperature [K], pressure difference [Pa], log10 speed [m/s]) of
 * sealsim.structure.maps.HermiteGrid, clamped to its axes.  The numba kernel reads each
 * cell's 64 coefficients (SteadyFrictionTable.tables()); this code reads the 8x smaller node
 * layout (SteadyFrictionTable.node_tables(): an int64 row (n_T, n_p, n_u, n_vars) and one
 * double array: the three axes, then the node values and derivatives, shape
 * (n_T, n_p, n_u, 8, n_vars), entry m the derivative along the axes whose bit is set in m)
 * and forms each coefficient as HermiteGrid does -- the corner node's entry times the cell
 * widths of the differentiated axes, in axis order -- then sums in the kernel's order
 * (contact_table.cell_sums, terms of weight 0 skipped): the same operations, the same bits.
 * contact_steady (one cell search for the sliding speed and the speed the film has formed
 * for; also the film's decay rate at rest, dphi/dt = -decay phi), film_decay_rate (that rate
 * alone) and theta_contact_level are the ports of
 * sealsim.friction.compiled.contact_steady and the kernel theta_contact_level of
 * sealsim.friction.kernels; film_speed_rate and film_speed_affine those of the kernels of the
 * same names (the film state of the Theta law on its contact).  Tests compare them all with
 * the numba functions. */
#include <math.h>

/* the cubic Hermite basis functions (h00, h10, h01, h11) at t in [0, 1] (contact_table.hermite_basis) */
static void table_basis(double t, double *w) {
    double t2 = t * t, t3 = t2 * t;
    w[0] = 2 * t3 - 3 * t2 + 1;
    w[1] = t3 - 2 * t2 + t;
    w[2] = -2 * t3 + 3 * t2;
    w[3] = t3 - t2;
}

/* (cell index, local coordinate in [0, 1]) of x on the axis data[pos:pos + n], clamped
 * (contact_table.locate_on_axis) */
static long table_locate(const double *data, long pos, long n, double x, double *u) {
    double lo = data[pos], hi = data[pos + n - 1];
    x = fmin(fmax(x, lo), hi);
    long a = 0, b = n;                   /* numpy.searchsorted(axis, x, side="right") */
    while (a < b) {
        long mid = (a + b) >> 1;
        if (x < data[pos + mid]) b = mid;
        else a = mid + 1;
    }
    long i = a - 1;
    if (i < 0) i = 0;
    if (i > n - 2) i = n - 2;
    *u = (x - data[pos + i]) / (data[pos + i + 1] - data[pos + i]);
    return i;
}

/* contact_table.cell_sum on the node layout for the n variables vars[] at once into out[]:
 * each basis term's coefficient is the corner node's derivative entry times the widths of
 * the differentiated axes (HermiteGrid); each variable's sum in the kernel's order */
static void table_cell_vars(const long *row, const double *data, long i, const double *wa,
                            long j, const double *wb, long k, const double *wc,
                            const long *vars, int n, double *out) {
    long nt = row[0], npr = row[1], nu = row[2], nv = row[3];
    double h0 = data[i + 1] - data[i];
    double h1 = data[nt + j + 1] - data[nt + j];
    double h2 = data[nt + npr + k + 1] - data[nt + npr + k];
    const double *nodes = data + nt + npr + nu;
    for (int m = 0; m < n; m++) out[m] = 0.0;
    for (int q0 = 0; q0 < 4; q0++) {
        double w0 = wa[q0];
        if (w0 == 0.0) continue;
        for (int q1 = 0; q1 < 4; q1++) {
            double w01 = w0 * wb[q1];
            if (w01 == 0.0) continue;
            for (int q2 = 0; q2 < 4; q2++) {
                double w = w01 * wc[q2];
                if (w == 0.0) continue;
                /* basis q = 2 corner + derivative order per axis */
                int mask = (q0 & 1) | (q1 & 1) << 1 | (q2 & 1) << 2;
                const double *node = nodes + ((((i + (q0 >> 1)) * npr + j + (q1 >> 1)) * nu +
                                               k + (q2 >> 1)) * 8 + mask) * nv;
                for (int m = 0; m < n; m++) {
                    double coefficient = node[vars[m]];
                    if (q0 & 1) coefficient *= h0;
                    if (q1 & 1) coefficient *= h1;
                    if (q2 & 1) coefficient *= h2;
                    out[m] += w * coefficient;
                }
            }
        }
    }
}

/* the asperity load and viscous friction of the direction whose load column is off (0: +,
 * 2: -), and with film != 0 its film, in one pass (contact_table.cell_sum each) */
static void table_cell_sums(const long *row, const double *data, long i, const double *wa,
                            long j, const double *wb, long k, const double *wc, long off,
                            int film, double *load, double *visc, double *thick) {
    long vars[3] = {off, off + 1, 4 + off / 2};
    double out[3];
    table_cell_vars(row, data, i, wa, j, wb, k, wc, vars, film ? 3 : 2, out);
    *load = out[0];
    *visc = out[1];
    *thick = film ? out[2] : 0.0;
}

/* contact_table.cell_sum of one variable var on the node layout */
static double table_cell_value(const long *row, const double *data, long i, const double *wa,
                               long j, const double *wb, long k, const double *wc, long var) {
    double out;
    table_cell_vars(row, data, i, wa, j, wb, k, wc, &var, 1, &out);
    return out;
}

/* contact_table.FILM_DECAY: the column of the film's decay rate */
#define FILM_DECAY 6

void contact_table_point(const long *row, const double *data, double temperature,
                         double pressure, double speed, double *load, double *visc,
                         double *film) {
    double a, b, c, wa[4], wb[4], wc[4];
    *load = *visc = *film = 0.0;
    if (speed == 0.0) return;
    long i = table_locate(data, 0, row[0], temperature, &a);
    long j = table_locate(data, row[0], row[1], pressure, &b);
    long k = table_locate(data, row[0] + row[1], row[2], log10(fabs(speed)), &c);
    table_basis(a, wa);
    table_basis(b, wb);
    table_basis(c, wc);
    table_cell_sums(row, data, i, wa, j, wb, k, wc, speed > 0.0 ? 0 : 2, 1, load, visc, film);
}

/* the speed cell of the film's speed film [m/s]; no film (film <= 0 or not a number): the
 * table's slowest speed, its first node (contact_table._film_cell) */
static long film_cell(const long *row, const double *data, double film, double *wc) {
    if (film > 0.0) {
        double c;
        long k = table_locate(data, row[0] + row[1], row[2], log10(film), &c);
        table_basis(c, wc);
        return k;
    }
    wc[0] = 1.0;
    wc[1] = wc[2] = wc[3] = 0.0;
    return 0;
}

void contact_steady(const long *row, const double *data, double temperature, double pressure,
                    double oriented_speed, double film, double circumference,
                    double boundary_friction, double *steady, double *boundary,
                    double *viscous, double *decay) {
    double a, b, wa[4], wb[4], wc[4], load, visc = 0.0, sums[3];
    long i = table_locate(data, 0, row[0], temperature, &a);       /* one cell search */
    long j = table_locate(data, row[0], row[1], pressure, &b);
    long k;
    table_basis(a, wa);
    table_basis(b, wb);
    if (oriented_speed != 0.0) {
        double c;
        long direction = oriented_speed > 0.0 ? 0 : 2;
        /* the asperity load and the film's decay rate at the film's speed, the viscous
         * friction at the sliding speed (one pass where they are the same) */
        long vars[3] = {direction, FILM_DECAY, direction + 1};
        int steady_film = film == fabs(oriented_speed);
        k = table_locate(data, row[0] + row[1], row[2], log10(fabs(oriented_speed)), &c);
        table_basis(c, wc);
        if (!steady_film) {
            visc = table_cell_value(row, data, i, wa, j, wb, k, wc, direction + 1);
            k = film_cell(row, data, film, wc);
        }
        table_cell_vars(row, data, i, wa, j, wb, k, wc, vars, steady_film ? 3 : 2, sums);
        load = sums[0];
        *decay = sums[1];
        if (steady_film) visc = sums[2];
    } else {                   /* at rest: the larger load the film leaves of both ways */
        long vars[3] = {0, 2, FILM_DECAY};
        k = film_cell(row, data, film, wc);
        table_cell_vars(row, data, i, wa, j, wb, k, wc, vars, 3, sums);
        load = fmax(sums[0], sums[1]);
        *decay = sums[2];
    }
    *steady = circumference * (boundary_friction * load + visc);
    *boundary = circumference * boundary_friction * load;
    *viscous = circumference * visc;
}

double film_decay_rate(const long *row, const double *data, double temperature,
                       double pressure, double film) {
    double a, b, wa[4], wb[4], wc[4];
    long i = table_locate(data, 0, row[0], temperature, &a);
    long j = table_locate(data, row[0], row[1], pressure, &b);
    table_basis(a, wa);
    table_basis(b, wb);
    long k = film_cell(row, data, film, wc);
    return table_cell_value(row, data, i, wa, j, wb, k, wc, FILM_DECAY);
}

double theta_contact_level(double th, double v, double fss, double fb, double d,
                           double thss, double fv) {
    double drop = d * fb, floor = 1e-9, level;
    if (v != 0.0) {            /* not below the film's viscous shear fv */
        level = fss + drop * (thss - th);
        floor = fv > floor ? fv : floor;
    } else {                   /* fss: the level the film leaves (contact_steady at rest) */
        level = fss - drop * th;
    }
    return level > floor ? level : floor;
}

/* kernels.FILM_MIN_LENGTH: the shortest length [m] over which the film follows the speed */
#define FILM_MIN_LENGTH 1e-6

/* the larger of b and FILM_MIN_LENGTH as Python's max(b, FILM_MIN_LENGTH) */
static double film_length(double b) {
    return FILM_MIN_LENGTH > b ? FILM_MIN_LENGTH : b;
}

double film_speed_rate(double phi, double v, double b, double decay) {
    double speed = fabs(v);
    return (speed - phi) * (speed / film_length(b) + decay);
}

void film_speed_affine(double v, double dt, double b, double decay, double *a, double *c) {
    double speed = fabs(v);
    double rate = -expm1(-(speed / film_length(b) + decay) * dt);
    *a = 1.0 - rate;
    *c = speed * rate;
}
