/* The pneumatic cylinder: chambers, valve, seals with their contact maps and friction laws,
 * end stops -- the right-hand side of sealsim.pneumatic.rhs in C, with its stick/slip modes.
 *
 * Every function below is a line-by-line port of the compiled (numba) function named next to
 * it (a seal's contact friction table: contact_table.c); the tables (constants CYL_C[], seal
 * tables, contact maps, friction tables) are those of
 * sealsim.pneumatic.system.PneumaticSystem, written into config.h by
 * sealsim.fmu.cylinder_export with the index macros of sealsim.pneumatic.rhs.  The build
 * check compares this right-hand side with the numba one at random states.
 *
 * States (x, v, m1, m2, U1, U2, the friction states of the seals) as in the Python model;
 * a change of the valve command input reaches the spool after the valve's dead time, then
 * the spool follows with its first-order lag, exactly (s = u + (s0 - u) exp(-(t - a)/tau)
 * from the arrival a: sealsim.pneumatic.valve.SpoolMotion); arrivals are time events (model
 * exchange) and restart points of the integrator (co-simulation), as in
 * sealsim.pneumatic.integrate.  Sticking seals (Coulomb, Stribeck, Theta without
 * bristles) make the model hybrid (sealsim.pneumatic.simulation): model exchange has one
 * event indicator and switches the mode in event mode; co-simulation integrates with the
 * BDF method of bdf.c (the port of sealsim.ode.bdf) and locates the stick/slip events
 * inside the step, as sealsim.pneumatic.integrate.run_interval. */
#include "sealsim_fmu.h"
#include "bdf.h"

#define P(name) (c->r[VR_##name])
#define TINY_SPEED 1e-300
#define MAX_SWITCHES_PER_MS 200

/* -- friction kernels (sealsim.friction.kernels) ------------------------------------------- */
static double sgn(double x) { return (double)((x > 0.0) - (x < 0.0)); }

static double power(double x, double e) {           /* kernels.power */
    if (e == 2.0) return x * x;
    if (e == 1.0) return x;
    if (e == 0.0) return 1.0;
    return pow(x, e);
}

static double stribeck_level(double v, double fc, double fs, double vs, double d) {
    return fc + (fs - fc) * exp(-power(fabs(v / vs), d));
}

static double lugre_bristle_rate(double z, double v, double s0, double g) {
    return v - s0 * fabs(v) * z / g;
}

static double theta_friction_level(double th, double fn, double fa, double fb) {
    return fn * (fa * (1.0 - th) + fb * th);
}

static double theta_rate(double th, double v, double tau, double al, double fn, double fref,
                         double n) {
    double p = power(fn / fref, n);
    return -th / tau + fabs(v) / (al * p) * (1.0 - th);
}

static double theta_steady(double v, double tau, double al, double fn, double fref,
                           double n) {
    double speed = fabs(v);
    if (speed > 0.0) return speed / (speed + al / tau * power(fn / fref, n));
    return 0.0;
}

/* kernels.walther_viscosity: nu(T) [mm2/s] (ASTM D341); nu(T_ref) is par[16] of the law */
static double walther_viscosity(double t, double wa, double wb) {
    return pow(10.0, pow(10.0, wa - wb * log10(t))) - 0.7;
}

static double gms_element_rate(double z, double v, double k, double frac, double cc,
                               double s) {
    double force = k * z, sv = sgn(v);
    if (force * sv < frac * s) return v;
    return cc / k * (frac * sv - force / s);
}

/* sealsim.friction.compiled.law_rates: (force, break-away); the state rates into dz; frow,
 * fdata, dp, orient: the contact friction table of a Theta law with steady = "contact" */
static double law_rates(long law, const double *par, const double *z, double vv, double fn,
                        double b, double pa, double pb, double temp, double *dz, double *brk,
                        const long *frow, const double *fdata, double dp, double orient) {
    double force = 0.0;
    *brk = 0.0;
    if (law == LAW_COULOMB) {
        double fc = par[0] + par[2] * (pa + pb);
        force = fc * sgn(vv) + par[1] * vv;
        *brk = fc;
    } else if (law == LAW_STRIBECK) {
        double fcp = par[0] + par[5] * (pa + pb);
        double fs = par[0] > 0.0 ? par[1] * fcp / par[0] : par[1] + (fcp - par[0]);
        force = stribeck_level(vv, fcp, fs, par[2], par[3]) * sgn(vv) + par[4] * vv;
        *brk = fs;
    } else if (law == LAW_LUGRE) {
        double g = stribeck_level(vv, par[3], par[4], par[5], par[6]);
        double zdot = lugre_bristle_rate(z[0], vv, par[0], g);
        force = par[0] * z[0] + par[1] * zdot + par[2] * vv;
        dz[0] = zdot;
    } else if (law == LAW_DAHL) {
        double u = 1.0 - par[0] * z[0] * sgn(vv) / par[1];
        if (u < 0.0) u = 0.0;
        force = par[0] * z[0];
        dz[0] = vv * power(u, par[2]);
    } else if (law == LAW_GMS) {
        int n = (int)par[0];
        double s = stribeck_level(vv, par[3], par[4], par[5], par[6]), total = 0.0;
        for (int j = 0; j < n; j++) {
            total += par[7 + j] * z[j];
            dz[j] = gms_element_rate(z[j], vv, par[7 + j], par[7 + n + j], par[1], s);
        }
        force = total + par[2] * vv;
    } else if (law == LAW_THETA) {
        int contact = par[12] > 0.0;
        double gamma = par[4];
        if (contact) gamma = 0.0;           /* the table holds the viscous part */
        else if (par[11] != 0.0) gamma *= walther_viscosity(temp, par[10], par[11]) / par[16];
        double th = z[0], level;
        fn = fmax_inline(fn, 1e-9);
        if (contact) {                      /* compiled._theta_level on the contact table */
            int last = par[7] > 0.0 ? 2 : 1;        /* the film's speed: the law's last state */
            double film = z[last], fss, fb, fv, decay;
            contact_steady(frow, fdata, temp, dp, orient * vv, film, par[15], par[13], &fss,
                           &fb, &fv, &decay);
            dz[last] = film_speed_rate(film, vv, b, decay);
            level = theta_contact_level(th, vv, fss, fb, par[14],
                                        theta_steady(vv, par[0], par[1], fn, par[5], par[6]), fv);
        } else {
            level = theta_friction_level(th, fn, par[2], par[3]);
        }
        dz[0] = theta_rate(th, vv, par[0], par[1], fn, par[5], par[6]);
        if (par[7] > 0.0) {
            double zdot = lugre_bristle_rate(z[1], vv, par[7], level);
            dz[1] = zdot;
            force = par[7] * z[1] + par[8] * zdot + gamma * b * vv;
        } else if (contact) {
            force = level * sgn(vv);
            *brk = level;
        } else {
            force = level * sgn(vv) + gamma * b * vv;
            *brk = level;
        }
    }
    return force;
}

/* -- contact maps (sealsim.pneumatic.contact_maps) ------------------------------------------ */
/* analytic_loads: F' = F'_0 + dp b(F') in closed form, Hertz width; F_N = pi D F' */
static void analytic_loads(double dp, double f0, double modulus, double d, double diameter,
                           double *fn, double *b) {
    const double pi = 3.141592653589793;
    double e_star = modulus / (1.0 - 0.5 * 0.5);
    double k = 2.0 * sqrt(2.0 * d / (pi * e_star));
    double kdp = k * fmax_inline(dp, 0.0);
    double root = 0.5 * (kdp + sqrt(kdp * kdp + 4.0 * f0));
    double force = root * root;
    *fn = pi * diameter * force;
    *b = 2.0 * sqrt(4.0 * fmax_inline(force, 0.0) * (0.5 * d) / (pi * e_star));
}

static double grid_basis(double u, int j) {       /* contact_maps._basis */
    double t2 = u * u, t3 = t2 * u;
    if (j == 0) return 2 * t3 - 3 * t2 + 1;
    if (j == 1) return t3 - 2 * t2 + u;
    if (j == 2) return -2 * t3 + 3 * t2;
    return t3 - t2;
}

static long search_right(const double *axis, long n, double x) {
    long lo = 0, hi = n;                 /* numpy.searchsorted(axis, x, side="right") */
    while (lo < hi) {
        long mid = (lo + hi) / 2;
        if (x < axis[mid]) hi = mid;
        else lo = mid + 1;
    }
    return lo;
}

/* hermite_grid_point: the C1 tensor-product Hermite interpolant of an FE map */
static void hermite_grid_point(const long *row, double pressure, double temperature,
                               double *fn, double *b, double *clipped) {
    const double *data = MAP_DATA;
    long o = row[1], d = row[2];
    double plo = data[o + 1], phi = data[o + 2], tlo = data[o + 3], thi = data[o + 4];
    double p = fmin_inline(fmax_inline(pressure, plo), phi);
    double t = fmin_inline(fmax_inline(temperature, tlo), thi);
    *clipped = fabs(t - temperature) > 1e-9 * fmax_inline(fabs(temperature), 1.0) ? 1.0 : 0.0;
    long pos = o + 5, cell = 0;
    double u[3] = {0.0, 0.0, 0.0};
    for (long k = 0; k < d; k++) {
        long role = row[3 + k], n = row[6 + k];
        const double *axis = data + pos;
        double x = role == 0 ? data[o] : (role == 1 ? t : p);
        long i = search_right(axis, n, x) - 1;
        if (i < 0) i = 0;
        else if (i >= n - 1) i = n - 2;
        u[k] = (x - axis[i]) / (axis[i + 1] - axis[i]);
        cell = cell * (n - 1) + i;
        pos += n;
    }
    long nvars = row[9], nb = d == 1 ? 4 : (d == 2 ? 16 : 64);
    long base = pos + cell * nb * nvars;
    *fn = 0.0;
    *b = 0.0;
    for (long j = 0; j < nb; j++) {
        double w;
        if (d == 1) w = grid_basis(u[0], (int)j);
        else if (d == 2) w = grid_basis(u[0], (int)(j / 4)) * grid_basis(u[1], (int)(j % 4));
        else w = grid_basis(u[0], (int)(j / 16)) * grid_basis(u[1], (int)((j / 4) % 4)) *
                 grid_basis(u[2], (int)(j % 4));
        *fn += w * data[base + j * nvars + row[10]];
        *b += w * data[base + j * nvars + row[11]];
    }
}

static void seal_loads(int i, double dp, double temp, double *fn, double *b, double *clipped) {
    const long *row = MAP_INT[i];
    *clipped = 0.0;
    if (row[0] == MAP_ANALYTIC) {
        const double *m = MAP_DATA + row[1];
        analytic_loads(dp, m[0], m[1], m[2], m[3], fn, b);
    } else if (row[0] == MAP_GRID) {
        hermite_grid_point(row, dp, temp, fn, b, clipped);
    } else {
        *fn = NAN;
        *b = NAN;
    }
}

/* -- valve, chambers, cylinder (sealsim.pneumatic.valve, .chambers, .cylinder) --------------- */
static double series_pair(double c1, double c2) {
    double small = fmin_inline(c1, c2), large = fmax_inline(c1, c2);
    double s = fmin_inline(small, 1e100), l = fmin_inline(large, 1e100);
    double ratio = s / (l + (l == 0.0));
    return small / sqrt(1.0 + ratio * ratio);
}

static double iso6358_mass_flow(double p1, double p2, double t1, double cond, double bcrit,
                                double m, double beta) {
    double r = fmin_inline(fmax_inline(p2 / p1, 0.0), 1.0);
    double e = (fmin_inline(fmax_inline(r, bcrit), beta) - bcrit) / (1.0 - bcrit);
    double q = 1.0 - e * e;        /* valve.subsonic_power: sqrt for m = 0.5, as numba */
    double phi = (m == 0.5 ? sqrt(q) : pow(q, m)) * fmin_inline((1.0 - r) / (1.0 - beta), 1.0);
    double g = cond * ANR_DENSITY * p1 * sqrt(ANR_TEMPERATURE / t1) * phi;
    return g * (p1 > p2);
}

static double iso6358_flow(double pa, double ta, double pb, double tb, double cond,
                           double bcrit, double m, double beta) {
    int forward = pa >= pb;
    double g = iso6358_mass_flow(fmax_inline(pa, pb), fmin_inline(pa, pb),
                                 forward * ta + (1 - forward) * tb, cond, bcrit, m, beta);
    return g * (2 * forward - 1);
}

static double cushion_conductance(double distance, double length, double conductance,
                                  double entry) {
    if (length <= 0.0) return INFINITY;
    double u = fmin_inline(fmax_inline((distance - (length - entry)) / entry, 0.0), 1.0);
    double closed = 1.0 - u * u * (3.0 - 2.0 * u);
    return closed <= 0.0 ? INFINITY : conductance / closed;
}

static void openings(double s, double centre, double *o) {
    double forward = fmin_inline(fmax_inline(s, 0.0), 1.0);
    double back = fmin_inline(fmax_inline(-s, 0.0), 1.0);
    double middle = 1.0 - forward - back;
    double exhaust = middle * (centre == 1.0), pressure = middle * (centre == 2.0);
    o[0] = forward + pressure;
    o[1] = back + exhaust;
    o[2] = back + pressure;
    o[3] = forward + exhaust;
}

static double end_stop_force(double x, double v, double stroke, double k, double cd,
                             double depth) {
    double d_cap = fmax_inline(-x, 0.0), d_head = fmax_inline(x - stroke, 0.0);
    double f_cap = fmax_inline(k * d_cap - cd * v * d_cap / (d_cap + depth), 0.0);
    double f_head = fmax_inline(k * d_head + cd * v * d_head / (d_head + depth), 0.0);
    return f_cap - f_head;
}

static double smooth_abs(double x, double eps) { return x * tanh(x / eps); }

/* friction_tables.table_orientation: the sign that turns the piston velocity into the
 * direction of a seal's friction table */
static double table_orientation(long code, double p1, double p2, double pa) {
    if (code == 0) return p2 > p1 ? 1.0 : -1.0;
    if (code == 1) return p2 >= pa ? 1.0 : -1.0;
    return 1.0;
}

/* -- the right-hand side (rhs.evaluate_column, levels RATES and OUTPUTS) --------------------- */
typedef struct {
    double x, v, p1, p2, t1, t2, spool, f_press, f_load, f_stop, f_fric, hold, brk;
    double f[NSEAL], fn[NSEAL], b[NSEAL], dp[NSEAL], clip[NSEAL], brk_seal[NSEAL];
    /* per chamber (cap, rod): the valve's net mass flow into it [kg/s], the net enthalpy
     * flow [W] and the heat from the wall [W] (rates only) */
    double flow_mass[2], flow_enthalpy[2], flow_heat[2];
} Outputs;

#define MAX_PENDING 16

typedef struct {
    double cst[C_NCONST];            /* CYL_C with the FMU's parameters and inputs */
    int mode;
    double command, t_command, s_command;   /* the spool's target, its arrival, s there */
    double last_input;                      /* the valve command input last seen */
    double pending_t[MAX_PENDING], pending_u[MAX_PENDING];  /* commands on their way */
    int npending;
    int bdf_active;
    double g_old;
    int event_pending;                      /* a stick/slip event located beyond t_end */
    double t_event;
    double recent[MAX_SWITCHES_PER_MS + 1];
    int recent_next;
    Bdf bdf;
} CylinderData;

#define DATA(c) ((CylinderData *)(void *)(c)->work)

/* rhs.spool_position: the lag towards u from s0 since the arrival a */
static double spool_lag(const CylinderData *m, double u, double s0, double a, double t) {
    double tau = m->cst[C_SPOOL_TAU];
    if (tau <= 0.0) return u;
    return u + (s0 - u) * exp(-fmax_inline(t - a, 0.0) / tau);
}

/* the spool at t, with the commands that arrive until t */
static double spool_position(const CylinderData *m, double t) {
    double u = m->command, s0 = m->s_command, a = m->t_command;
    for (int k = 0; k < m->npending && m->pending_t[k] <= t; k++) {
        s0 = spool_lag(m, u, s0, a, m->pending_t[k]);
        a = m->pending_t[k];
        u = m->pending_u[k];
    }
    return spool_lag(m, u, s0, a, t);
}

/* make the commands that have arrived until t the spool's target; 1 if one arrived */
static int commit_arrivals(CylinderData *m, double t) {
    int arrived = 0;
    while (m->npending > 0 && m->pending_t[0] <= t) {
        m->s_command = spool_lag(m, m->command, m->s_command, m->t_command, m->pending_t[0]);
        m->t_command = m->pending_t[0];
        m->command = m->pending_u[0];
        for (int k = 1; k < m->npending; k++) {
            m->pending_t[k - 1] = m->pending_t[k];
            m->pending_u[k - 1] = m->pending_u[k];
        }
        m->npending--;
        arrived = 1;
    }
    return arrived;
}

/* what evaluate computes (rhs.evaluate_column's level): the outputs only, the rates too, the
 * rates with each seal's contact loads of the evaluation before in o (a Jacobian column that
 * changes no pressure difference) */
enum { OUTPUTS_ONLY = 0, RATES = 1, RATES_KEPT_LOADS = 2 };

/* chamber k's (0 cap, 1 rod) air flows at pressure p and temperature t into o: from the
 * supply through the valve opening op_in and to the atmosphere through op_out, each in series
 * with the chamber's line (its throttle and end cushion, conductance `line`) where the air
 * leaves the chamber (ISO 6358), the enthalpy they carry, and the heat from its wall of area
 * wall_area at the wall temperature */
static void chamber_flows(const double *c, int k, double p, double t, double line,
                          double op_in, double op_out, double wall_area, Outputs *o) {
    double ps = c[C_PS], pa = c[C_PA], ts = c[C_TS], ta = c[C_TA];
    double k_in = series_pair(c[C_C] * op_in, p > ps ? line : INFINITY);
    double k_out = series_pair(c[C_C] * op_out, p > pa ? line : INFINITY);
    double g_in = iso6358_flow(ps, ts, p, t, k_in, c[C_B], c[C_M], c[C_BETA]);
    double g_out = iso6358_flow(p, t, pa, ta, k_out, c[C_B], c[C_M], c[C_BETA]);
    o->flow_mass[k] = g_in - g_out;
    o->flow_enthalpy[k] = AIR_CP * (ps >= p ? ts : t) * g_in - AIR_CP * (p >= pa ? t : ta) * g_out;
    o->flow_heat[k] = c[C_H] * wall_area * (c[C_TW] - t);
}

/* the chambers whose flows (Outputs.flow_...) an evaluation of the rates takes from o instead
 * of computing them: what a Jacobian column that changes no state of that chamber keeps */
enum { KEEP_CAP_FLOWS = 1, KEEP_ROD_FLOWS = 2 };

/* the model at the states y with the spool at s (spool_position at the time; the time enters
 * nowhere else); kept_flows: the chambers whose flows o holds (KEEP_..._FLOWS, 0: none) */
static void evaluate(const CylinderData *m, double s, const double *y, int mode, int level,
                     int kept_flows, double *dy, Outputs *o) {
    const double *c = m->cst;
    const double gm1 = AIR_GAMMA - 1.0;
    double x = y[0], v = y[1], m1 = y[2], m2 = y[3], u1 = y[4], u2 = y[5];
    double vol1 = c[C_DEAD1] + c[C_A1] * x, vol2 = c[C_DEAD2] + c[C_A2] * (c[C_STROKE] - x);
    double p1 = gm1 * u1 / vol1, p2 = gm1 * u2 / vol2;
    double t1 = fmin_inline(fmax_inline(u1 / (fmax_inline(m1, 1e-12) * AIR_CV), 20.0), 3000.0);
    double t2 = fmin_inline(fmax_inline(u2 / (fmax_inline(m2, 1e-12) * AIR_CV), 20.0), 3000.0);
    double pa = c[C_PA];
    double op[4];
    if (level != OUTPUTS_ONLY && (kept_flows & (KEEP_CAP_FLOWS | KEEP_ROD_FLOWS)) !=
                                     (KEEP_CAP_FLOWS | KEEP_ROD_FLOWS))
        openings(s, c[C_CENTRE], op);
    /* wall areas: affine in x, from chambers.chamber_wall_areas (no seal heating here: the
     * rod's surface is at the wall temperature too) */
    if (level != OUTPUTS_ONLY && !(kept_flows & KEEP_CAP_FLOWS))
        chamber_flows(c, 0, p1, t1, series_pair(c[C_THR1], cushion_conductance(
                          x, c[C_CU1_L], c[C_CU1_C], c[C_CU1_E])),
                      op[0], op[1], c[C_AW1] + c[C_AW1_X] * x, o);
    if (level != OUTPUTS_ONLY && !(kept_flows & KEEP_ROD_FLOWS))
        chamber_flows(c, 1, p2, t2, series_pair(c[C_THR2], cushion_conductance(
                          c[C_STROKE] - x, c[C_CU2_L], c[C_CU2_C], c[C_CU2_E])),
                      op[2], op[3], c[C_AW2] + c[C_AW2_X] * x, o);
    double f_press = p1 * c[C_A1] - p2 * c[C_A2] - pa * c[C_AROD];
    double f_load = c[C_F0] + c[C_KL] * (x - c[C_X0L]) + c[C_MASS] * GRAVITY * sin(c[C_INCL]) +
                    c[C_CL] * v;
    double f_stop = end_stop_force(x, v, c[C_STROKE], c[C_KS], c[C_CS], c[C_DS]);
    double f_drive = f_press - f_load + f_stop;
    int sticky_any = 0, nsticky = 0;
    double f_smooth = 0.0, brk_sum = 0.0, f_fric = 0.0, dz[16];
    for (int i = 0; i < NSEAL; i++) {
        long law = SEAL_INT[i][SI_LAW], loc = SEAL_INT[i][SI_LOC], off = SEAL_INT[i][SI_OFF];
        int sticky = SEAL_INT[i][SI_STICKY] != 0;
        double temp = SEAL_THERM[i][ST_TCONST];
        double dp = loc == 0 ? smooth_abs(p1 - p2, 1e3)
                             : (loc == 1 ? smooth_abs(p2 - pa, 1e3) : 0.0);
        double side_a = (loc == 0) * (p1 - pa) + (loc == 1) * (p2 - pa);
        double side_b = (loc == 0) * (p2 - pa);
        double fn, b, clipped, vv, brk;
        if (level == RATES_KEPT_LOADS) {
            fn = o->fn[i];
            b = o->b[i];
            clipped = o->clip[i];
        } else {
            seal_loads(i, dp, temp, &fn, &b, &clipped);
        }
        if (!sticky || mode == MODE_FREE || mode == MODE_PRESCRIBED) vv = v;
        else if (mode == MODE_STICK) vv = 0.0;
        else {
            double d = (double)mode;
            vv = d * fmax_inline(d * v, TINY_SPEED);
        }
        double force = law_rates(law, LAW_PAR[i], y + off, vv, fn, b, side_a, side_b, temp, dz,
                                 &brk, FRIC_INT[i] + 1, FRIC_DATA + FRIC_INT[i][0], dp,
                                 table_orientation(loc, p1, p2, pa));
        if (level != OUTPUTS_ONLY) {
            int ns = SEAL_NSTATES[i];
            for (int j = 0; j < ns; j++) dy[off + j] = dz[j];
        }
        if (sticky) {
            sticky_any = 1;
            nsticky++;
            brk_sum += brk;
            if (mode == MODE_STICK) force = 0.0;
        } else {
            f_smooth += force;
        }
        o->f[i] = force;
        o->fn[i] = fn;
        o->b[i] = b;
        o->dp[i] = dp;
        o->clip[i] = clipped;
        o->brk_seal[i] = brk;
    }
    double hold = 0.0;
    if (mode == MODE_STICK && sticky_any) {
        hold = f_drive - f_smooth;
        for (int i = 0; i < NSEAL; i++) {
            if (SEAL_INT[i][SI_STICKY] != 0)
                o->f[i] = brk_sum > 0.0 ? o->brk_seal[i] / brk_sum * hold : 1.0 / nsticky * hold;
        }
    }
    for (int i = 0; i < NSEAL; i++) f_fric += o->f[i];
    if (level != OUTPUTS_ONLY) {
        dy[0] = v;
        dy[1] = (mode == MODE_FORWARD || mode == MODE_BACKWARD || mode == MODE_FREE)
                    ? (f_drive - f_fric) / c[C_MASS] : 0.0;
        double dvol1 = c[C_A1] * v, dvol2 = -c[C_A2] * v;
        dy[2] = o->flow_mass[0];
        dy[3] = o->flow_mass[1];
        dy[4] = o->flow_enthalpy[0] - p1 * dvol1 + o->flow_heat[0];
        dy[5] = o->flow_enthalpy[1] - p2 * dvol2 + o->flow_heat[1];
    }
    o->x = x;
    o->v = v;
    o->p1 = p1;
    o->p2 = p2;
    o->t1 = t1;
    o->t2 = t2;
    o->spool = s;
    o->f_press = f_press;
    o->f_load = f_load;
    o->f_stop = f_stop;
    o->f_fric = f_fric;
    o->hold = hold;
    o->brk = brk_sum;
}

/* the instance memory must hold the model's data */
typedef char cylinder_work_fits[(sizeof(CylinderData) <= sizeof(((Instance *)0)->work)) ? 1 : -1];

/* -- the problem of bdf.c: the right-hand side in one mode ---------------------------------- */
typedef struct {
    CylinderData *m;
    int mode;
    Outputs o;
    BdfProblem bp;
    double spool_t, spool_s;         /* the spool position spool_s at the time spool_t */
    double shifted[NSTATES], f1[NSTATES], rest[NSTATES];
} Problem;

/* the spool at t: the Newton iterations of a step and the columns of its Jacobian all
 * evaluate at the same time, so the last one is kept (an exp() per right-hand side less) */
static double problem_spool(Problem *p, double t) {
    if (t != p->spool_t) {
        p->spool_s = spool_position(p->m, t);
        p->spool_t = t;
    }
    return p->spool_s;
}

static void problem_fun(void *ctx, double t, const double *y, double *dy) {
    Problem *p = (Problem *)ctx;
    evaluate(p->m, problem_spool(p, t), y, p->mode, RATES, 0, dy, &p->o);
}

/* the chambers whose air a change of state j leaves as it is: x moves both volumes, m1 and U1
 * are the cap-end air, m2 and U2 the rod-end air, v and the friction states neither */
static int chambers_kept(int j) {
    if (j == 0) return 0;
    if (j == 2 || j == 4) return KEEP_ROD_FLOWS;
    if (j == 3 || j == 5) return KEEP_CAP_FLOWS;
    return KEEP_CAP_FLOWS | KEEP_ROD_FLOWS;
}

/* rhs.jacobian_at: forward differences from f = f(t, y), which the integrator has evaluated,
 * h_j = 1.5e-8 max(|y_j|, scale_j); the columns that change no pressure (all but x, U1, U2)
 * first, the first of them looks the contact loads up, the others keep them.  The valve and
 * wall flows of a chamber whose air a column leaves as it is are those at y, from the first
 * column that changes no chamber (v): the same numbers, half of the columns' flows */
static void problem_jac(void *ctx, double t, const double *y, const double *f, double *J) {
    Problem *p = (Problem *)ctx;
    double s = problem_spool(p, t);
    double flow_mass[2], flow_enthalpy[2], flow_heat[2];     /* the flows at y */
    int looked_up = 0, flows_at_y = 0;
    for (int sweep = 0; sweep < 2; sweep++) {
        for (int j = 0; j < NSTATES; j++) {
            int new_loads = j == 0 || j == 4 || j == 5;
            if (new_loads != (sweep == 1)) continue;
            double h = 1.5e-8 * fmax_inline(fabs(y[j]), JAC_SCALE[j]);
            for (int i = 0; i < NSTATES; i++) p->shifted[i] = y[i];
            p->shifted[j] = y[j] + h;
            int kept = flows_at_y ? chambers_kept(j) : 0;
            for (int k = 0; kept && k < 2; k++) {
                p->o.flow_mass[k] = flow_mass[k];
                p->o.flow_enthalpy[k] = flow_enthalpy[k];
                p->o.flow_heat[k] = flow_heat[k];
            }
            evaluate(p->m, s, p->shifted, p->mode,
                     new_loads || !looked_up ? RATES : RATES_KEPT_LOADS, kept, p->f1, &p->o);
            looked_up = 1;
            if (!flows_at_y && chambers_kept(j) == (KEEP_CAP_FLOWS | KEEP_ROD_FLOWS)) {
                for (int k = 0; k < 2; k++) {
                    flow_mass[k] = p->o.flow_mass[k];
                    flow_enthalpy[k] = p->o.flow_enthalpy[k];
                    flow_heat[k] = p->o.flow_heat[k];
                }
                flows_at_y = 1;
            }
            for (int i = 0; i < NSTATES; i++) J[i * BDF_MAXN + j] = (p->f1[i] - f[i]) / h;
        }
    }
}

/* integrate._renew: the growth rate from the velocity's column alone, from f = f(t, y)
 * (rhs.velocity_column_at: the column of problem_jac; it looks the contact loads up, as the
 * evaluation before need not have been at y) */
static double problem_renew(void *ctx, double t, const double *y, const double *f, double *J) {
    Problem *p = (Problem *)ctx;
    double h = 1.5e-8 * fmax_inline(fabs(y[1]), JAC_SCALE[1]);
    for (int i = 0; i < NSTATES; i++) p->shifted[i] = y[i];
    p->shifted[1] = y[1] + h;
    evaluate(p->m, problem_spool(p, t), p->shifted, p->mode, RATES, 0, p->f1, &p->o);
    for (int i = 0; i < NSTATES; i++) J[i * BDF_MAXN + 1] = (p->f1[i] - f[i]) / h;
    return fmax_inline(J[1 * BDF_MAXN + 1], 0.0);
}

/* integrate._growth: the piston's own velocity feedback where positive */
static double problem_growth(void *ctx, double t, const double *y, const double *J) {
    (void)ctx;
    (void)t;
    (void)y;
    return fmax_inline(J[1 * BDF_MAXN + 1], 0.0);
}

/* integrate._margin: (F_req, F_brk + stick_tolerance) with the body held at rest */
static void stick_margin(Problem *p, double t, const double *y, double *hold, double *brk) {
    for (int i = 0; i < NSTATES; i++) p->rest[i] = y[i];
    p->rest[1] = 0.0;
    evaluate(p->m, problem_spool(p, t), p->rest, MODE_STICK, OUTPUTS_ONLY, 0, NULL, &p->o);
    *hold = p->o.hold;
    *brk = p->o.brk + (1e-4 * fabs(p->o.brk) + 1e-3);
}

/* integrate._event */
static double problem_event(void *ctx, double t, const double *y) {
    Problem *p = (Problem *)ctx;
    if (p->mode == MODE_FORWARD || p->mode == MODE_BACKWARD)
        return p->mode * y[1] + SPEED_RESOLUTION;
    if (p->mode == MODE_STICK) {
        double hold, brk;
        stick_margin(p, t, y, &hold, &brk);
        return fabs(hold) - brk;
    }
    return 1.0;
}

static int next_mode_at_rest(Problem *p, double t, const double *y) {
    double hold, brk;
    stick_margin(p, t, y, &hold, &brk);
    if (fabs(hold) <= brk) return MODE_STICK;
    return hold > 0 ? MODE_FORWARD : MODE_BACKWARD;
}

/* the mode after a stick/slip event (integrate.run_interval); v = 0 when coming to rest */
static int switch_mode(Problem *p, double t, double *y) {
    if (p->mode == MODE_FORWARD || p->mode == MODE_BACKWARD) {
        y[1] = 0.0;
        return next_mode_at_rest(p, t, y);
    }
    double hold, brk;
    stick_margin(p, t, y, &hold, &brk);
    return hold > 0 ? MODE_FORWARD : MODE_BACKWARD;
}

static void problem_init(Problem *p, CylinderData *m) {
    p->m = m;
    p->mode = m->mode;
    p->bp.ctx = p;
    p->bp.fun = problem_fun;
    p->bp.jac = problem_jac;
    p->bp.event = problem_event;
    p->bp.growth = problem_growth;
    p->bp.renew = problem_renew;
    p->spool_t = NAN;
}

/* -- the inputs ----------------------------------------------------------------------------- */
static void read_states(Instance *c, double *y) {
    for (int i = 0; i < NSTATES; i++) y[i] = c->r[STATE_VR[i]];
}

static void write_states(Instance *c, const double *y) {
    for (int i = 0; i < NSTATES; i++) c->r[STATE_VR[i]] = y[i];
}

/* take the inputs at the current time: a new valve command arrives at the spool after the
 * dead time; an arrival, or a new load, restarts the co-simulation integrator (a kink) */
static FmuStatus take_inputs(Instance *c) {
    CylinderData *m = DATA(c);
    double u = P(VALVE_COMMAND);
    if (!(u >= -1.0 && u <= 1.0)) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "valve_command = %g is not allowed: it must lie in [-1, 1] (+1 extend, "
                "-1 retract, 0 centre of a 5/3 valve)", u);
        return FMU_ERROR;
    }
    if (u != m->last_input) {
        if (m->npending == MAX_PENDING) {
            fmu_log(c, FMU_ERROR, "logStatusError",
                    "more than %d valve commands within the valve's dead time (%g s) at "
                    "t = %g s", MAX_PENDING, P(VALVE_DELAY), c->time);
            return FMU_ERROR;
        }
        m->pending_t[m->npending] = c->time + P(VALVE_DELAY);
        m->pending_u[m->npending] = u;
        m->npending++;
        m->last_input = u;
        /* the integrator, ahead of c->time, stepped past the new command's arrival with the
         * old one: it restarts from the state at c->time */
        if (m->bdf_active && m->bdf.t > c->time + P(VALVE_DELAY)) m->bdf_active = 0;
    }
    if (commit_arrivals(m, c->time)) m->bdf_active = 0;
    if (P(F_LOAD) != m->cst[C_F0]) {
        m->cst[C_F0] = P(F_LOAD);
        m->bdf_active = 0;
    }
    return FMU_OK;
}

/* -- the model interface -------------------------------------------------------------------- */
FmuStatus model_check_parameters(Instance *c) {
    (void)c;
    return FMU_OK;
}

FmuStatus model_initialize(Instance *c) {
    CylinderData *m = DATA(c);
    memset(m, 0, sizeof *m);
    for (int i = 0; i < C_NCONST; i++) m->cst[i] = CYL_C[i];
    m->cst[C_PS] = P(P_SUPPLY);
    m->cst[C_MASS] = P(MOVING_MASS);
    m->cst[C_C] = P(VALVE_CONDUCTANCE);
    m->cst[C_H] = P(HEAT_TRANSFER_COEFFICIENT);
    m->cst[C_F0] = P(F_LOAD);
    m->command = CYL_C[C_SPOOL_INIT];
    m->s_command = CYL_C[C_SPOOL_INIT];
    m->t_command = c->time;
    m->last_input = CYL_C[C_SPOOL_INIT];
    m->npending = 0;
    for (int i = 0; i <= MAX_SWITCHES_PER_MS; i++) m->recent[i] = -INFINITY;
    m->recent_next = 0;
    if (take_inputs(c) > FMU_WARNING) return FMU_ERROR;
    for (int i = 0; i < NSTATES; i++) c->nominals[i] = JAC_SCALE[i];
    m->mode = MODE_FREE;
    if (STICKY) {
        Problem p;
        double y[NSTATES];
        problem_init(&p, m);
        read_states(c, y);
        m->mode = next_mode_at_rest(&p, c->time, y);
    }
    return FMU_OK;
}

FmuStatus model_outputs(Instance *c) {
    CylinderData *m = DATA(c);
    Problem p;
    double y[NSTATES];
    if (take_inputs(c) > FMU_WARNING) return FMU_ERROR;
    problem_init(&p, m);
    read_states(c, y);
    evaluate(m, problem_spool(&p, c->time), y, m->mode, OUTPUTS_ONLY, 0, NULL, &p.o);
    const Outputs *o = &p.o;
    P(P1) = o->p1;
    P(P2) = o->p2;
    P(T1) = o->t1;
    P(T2) = o->t2;
    P(SPOOL) = o->spool;
    P(F_FRICTION) = o->f_fric;
    P(F_PRESSURE) = o->f_press;
    P(F_STOP) = o->f_stop;
    P(STUCK) = m->mode == MODE_STICK ? 1.0 : 0.0;
    for (int i = 0; i < NSEAL; i++) {
        c->r[SEAL_VR[i][0]] = o->f[i];
        c->r[SEAL_VR[i][1]] = o->fn[i];
        c->r[SEAL_VR[i][2]] = o->b[i];
        c->r[SEAL_VR[i][3]] = o->dp[i];
    }
#if NEVENT_INDICATORS > 0
    P(STICK_SLIP_INDICATOR) = problem_event(&p, c->time, y);
#endif
    /* pneumatic.system.check_chamber_volumes: a piston pressed into an end stop's bumper
     * deeper than the dead volume allows (a large F_load) leaves a chamber without volume */
    double volume_cap = m->cst[C_DEAD1] + m->cst[C_A1] * o->x;
    double volume_rod = m->cst[C_DEAD2] + m->cst[C_A2] * (m->cst[C_STROKE] - o->x);
    if (!(volume_cap > 0.0 && volume_rod > 0.0)) {
        int cap = !(volume_cap > 0.0);
        fmu_log(c, FMU_ERROR, "logStatusError",
                "at t = %g s the piston is %g mm deep in the %s end stop's bumper (x = %g m, "
                "F_load = %g N): more than the dead volume of that chamber (%g cm^3) allows, "
                "so it has no volume left; lower F_load or use a stiffer end stop", c->time,
                1e3 * (cap ? -o->x : o->x - m->cst[C_STROKE]), cap ? "cap-end" : "rod-end",
                o->x, P(F_LOAD), 1e6 * m->cst[cap ? C_DEAD1 : C_DEAD2]);
        return FMU_ERROR;
    }
    if (!isfinite(o->f_fric) || !isfinite(o->p1) || !isfinite(o->p2)) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "the model is not finite at t = %g s (x = %g m, v = %g m/s, p1 = %g Pa, "
                "p2 = %g Pa)", c->time, o->x, o->v, o->p1, o->p2);
        return FMU_ERROR;
    }
    return FMU_OK;
}

void model_derivatives(Instance *c, double *dx) {
    CylinderData *m = DATA(c);
    Outputs o;
    double y[NSTATES];
    read_states(c, y);
    evaluate(m, spool_position(m, c->time), y, m->mode, RATES, 0, dx, &o);
}

/* the next time event: the arrival of a command at the spool (model exchange) */
double model_next_event_time(Instance *c) {
    CylinderData *m = DATA(c);
    return m->npending > 0 ? m->pending_t[0] : INFINITY;
}

#if NEVENT_INDICATORS > 0
void model_event_indicators(Instance *c, double *z) {
    z[0] = P(STICK_SLIP_INDICATOR);
}

/* event mode: the stick/slip transition whose indicator crossed zero */
FmuStatus model_event_update(Instance *c, int *states_changed) {
    CylinderData *m = DATA(c);
    Problem p;
    double y[NSTATES];
    if (take_inputs(c) > FMU_WARNING) return FMU_ERROR;
    problem_init(&p, m);
    read_states(c, y);
    if (problem_event(&p, c->time, y) <= 0.0 && m->mode != MODE_STICK &&
        m->mode != MODE_FREE) {
        m->mode = switch_mode(&p, c->time, y);
        write_states(c, y);
        *states_changed = 1;
    } else if (m->mode == MODE_STICK && problem_event(&p, c->time, y) >= 0.0) {
        m->mode = switch_mode(&p, c->time, y);
    }
    return FMU_OK;
}
#endif

/* the next breakpoint of the integration: a command's arrival at the spool (the spool's
 * motion has a kink there), or none */
static double next_arrival(const CylinderData *m) {
    return m->npending > 0 ? m->pending_t[0] : INFINITY;
}

/* co-simulation: BDF (bdf.c) from t to t + h with the stick/slip events inside
 * (integrate.run_interval).  While the inputs stay the same the integrator's history is kept
 * between communication steps and its steps are not cut at the communication points: the
 * last step may end beyond t + h, the state there is its dense output (as the output grid of
 * sealsim pneumatic run; cutting every step at a 20 ms communication point doubled the
 * integration's cost), and an event located beyond t + h waits for the step that reaches it.
 * A command's arrival at the spool and a step of F_load restart the integrator there. */
FmuStatus model_step(Instance *c, double h) {
    CylinderData *m = DATA(c);
    Problem p;
    double y[NSTATES], y_tmp[NSTATES];
    double t = c->time, t_end = c->time + h;
    if (h <= 0.0) return FMU_OK;
    if (take_inputs(c) > FMU_WARNING) return FMU_ERROR;
    problem_init(&p, m);
    read_states(c, y);
    const BdfProblem *bp = &p.bp;
    Bdf *b = &m->bdf;
    for (;;) {
        if (m->bdf_active) {
            /* what the last step, which may reach beyond t_end, left: an event, a command's
             * arrival at its end, or t_end inside it */
            if (m->event_pending) {
                if (m->t_event > t_end) break;
                bdf_dense(b, m->t_event, y);
                t = m->t_event;
                m->event_pending = 0;
                m->mode = p.mode = switch_mode(&p, t, y);
                m->bdf_active = 0;
                /* chattering guard: more than MAX_SWITCHES_PER_MS switches within 1 ms */
                double oldest = m->recent[m->recent_next];
                m->recent[m->recent_next] = t;
                m->recent_next = (m->recent_next + 1) % (MAX_SWITCHES_PER_MS + 1);
                if (oldest > t - 1e-3) {
                    fmu_log(c, FMU_ERROR, "logStatusError",
                            "stick/slip chattering at t = %g s (more than %d transitions within "
                            "1 ms): check the friction parameters", t, MAX_SWITCHES_PER_MS);
                    return FMU_ERROR;
                }
                continue;
            }
            if (b->t >= next_arrival(m) && next_arrival(m) <= t_end) {
                t = b->t;
                for (int i = 0; i < NSTATES; i++) y[i] = b->y_new[i];
                commit_arrivals(m, t);
                m->bdf_active = 0;
                continue;
            }
            if (b->t >= t_end) break;
        } else {
            if (t >= t_end) break;
            /* a step of F_load restarts the integrator with the holding force beyond the
             * break-away already: no crossing left to find, so the piston breaks away here */
            if (m->mode == MODE_STICK && problem_event(&p, t, y) > 0.0)
                m->mode = p.mode = switch_mode(&p, t, y);
            bdf_init(b, NSTATES, RTOL, ATOL, MAX_STEP);
            bdf_start(b, t, y, next_arrival(m), bp);
            int moving = m->mode == MODE_FORWARD || m->mode == MODE_BACKWARD;
            m->g_old = (moving || m->mode == MODE_STICK) ? problem_event(&p, t, y) : 1.0;
            m->event_pending = 0;
            m->bdf_active = 1;
        }
        b->t_bound = next_arrival(m);
        if (bdf_step(b, bp) != BDF_OK) {
            fmu_log(c, FMU_ERROR, "logStatusError",
                    "the integrator failed at t = %g s (x = %g m, v = %g m/s): the step size "
                    "became too small", b->t, b->y_new[0], b->y_new[1]);
            return FMU_ERROR;
        }
        int direction = (m->mode == MODE_FORWARD || m->mode == MODE_BACKWARD) ? -1
                        : (m->mode == MODE_STICK ? 1 : 0);
        if (direction != 0) {
            double g_new = problem_event(&p, b->t, b->y_new);
            if ((direction > 0 && m->g_old <= 0.0 && 0.0 <= g_new) ||
                (direction < 0 && m->g_old >= 0.0 && 0.0 >= g_new)) {
                m->t_event = bdf_locate(b, bp, m->g_old, g_new, y_tmp);
                m->event_pending = 1;
            }
            m->g_old = g_new;
        }
    }
    /* the state at t_end: the dense output of the last step (or the restart point) */
    if (m->bdf_active) {
        bdf_dense(b, t_end, y);
        t = t_end;
    }
    if (m->mode == MODE_STICK) y[1] = 0.0;
    write_states(c, y);
    return FMU_OK;
}
