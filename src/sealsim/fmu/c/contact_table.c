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
 * widths of the differentiated axes, in axis order -- then sums in the kernel's order: the
 * same operations, the same bits.  contact_steady and theta_contact_level are the ports of
 * sealsim.friction.compiled.contact_steady and the kernel theta_contact_level of
 * sealsim.friction.kernels.  A test compares all three with the numba functions. */
#include <math.h>

/* cubic Hermite basis function q (h00, h10, h01, h11) at t in [0, 1] (contact_table._hermite) */
static double table_hermite(double t, int q) {
    double t2 = t * t, t3 = t2 * t;
    if (q == 0) return 2 * t3 - 3 * t2 + 1;
    if (q == 1) return t3 - 2 * t2 + t;
    if (q == 2) return -2 * t3 + 3 * t2;
    return t3 - t2;
}

/* (cell index, local coordinate in [0, 1]) of x on the axis data[pos:pos + n], clamped
 * (contact_table._locate) */
static long table_locate(const double *data, long pos, long n, double x, double *u) {
    double lo = data[pos], hi = data[pos + n - 1];
    x = fmin(fmax(x, lo), hi);
    long a = 0, b = n;                   /* numpy.searchsorted(axis, x, side="right") */
    while (a < b) {
        long mid = (a + b) / 2;
        if (x < data[pos + mid]) b = mid;
        else a = mid + 1;
    }
    long i = a - 1;
    if (i < 0) i = 0;
    else if (i > n - 2) i = n - 2;
    *u = (x - data[pos + i]) / (data[pos + i + 1] - data[pos + i]);
    return i;
}

void contact_table_point(const long *row, const double *data, double temperature,
                         double pressure, double speed, double *load, double *visc,
                         double *film) {
    *load = 0.0;
    *visc = 0.0;
    *film = 0.0;
    if (speed == 0.0) return;
    long nt = row[0], npr = row[1], nu = row[2], nv = row[3];
    double a, b, c;
    long i = table_locate(data, 0, nt, temperature, &a);
    long j = table_locate(data, nt, npr, pressure, &b);
    long k = table_locate(data, nt + npr, nu, log10(fabs(speed)), &c);
    double h0 = data[i + 1] - data[i];
    double h1 = data[nt + j + 1] - data[nt + j];
    double h2 = data[nt + npr + k + 1] - data[nt + npr + k];
    const double *nodes = data + nt + npr + nu;
    long off = speed > 0.0 ? 0 : 2;
    long fv = 4 + off / 2;
    for (int q0 = 0; q0 < 4; q0++) {
        double w0 = table_hermite(a, q0);
        for (int q1 = 0; q1 < 4; q1++) {
            double w01 = w0 * table_hermite(b, q1);
            for (int q2 = 0; q2 < 4; q2++) {
                double w = w01 * table_hermite(c, q2);
                /* basis q = 2 corner + derivative order per axis (HermiteGrid) */
                int mask = (q0 & 1) | (q1 & 1) << 1 | (q2 & 1) << 2;
                const double *node = nodes + ((((i + (q0 >> 1)) * npr + j + (q1 >> 1)) * nu +
                                               k + (q2 >> 1)) * 8 + mask) * nv;
                double cl = node[off], cv = node[off + 1], cf = node[fv];
                if (q0 & 1) { cl *= h0; cv *= h0; cf *= h0; }
                if (q1 & 1) { cl *= h1; cv *= h1; cf *= h1; }
                if (q2 & 1) { cl *= h2; cv *= h2; cf *= h2; }
                *load += w * cl;
                *visc += w * cv;
                *film += w * cf;
            }
        }
    }
}

void contact_steady(const long *row, const double *data, double temperature, double pressure,
                    double oriented_speed, double circumference, double boundary_friction,
                    double *steady, double *boundary) {
    double load, visc, up, down, unused0, unused1;
    contact_table_point(row, data, temperature, pressure, oriented_speed, &load, &visc,
                        &unused0);
    double slow = pow(10.0, data[row[0] + row[1]]);
    contact_table_point(row, data, temperature, pressure, slow, &up, &unused0, &unused1);
    contact_table_point(row, data, temperature, pressure, -slow, &down, &unused0, &unused1);
    *steady = circumference * (boundary_friction * load + visc);
    *boundary = circumference * boundary_friction * 0.5 * (up + down);
}

double theta_contact_level(double th, double v, double fss, double fb, double d,
                           double thss) {
    double drop = d * fb;
    double level = v != 0.0 ? fss + drop * (thss - th) : fb - drop * th;
    return level > 1e-9 ? level : 1e-9;
}
