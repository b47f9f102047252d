/* Rotary lip seal: steady maps of sealsim's coupled friction-thermal model plus a thermal lag.
 *
 * Coordinates (sealsim.fmu.rotary_maps.MapAxes): speed u = log(1 + |speed|/SPEED_SCALE); the
 * oil-side convection of the shaft changes its flow regime (Taylor-Couette: laminar to Taylor
 * vortices) at speeds e_1(T_sump) < ... that move with the oil's viscosity, and the steady
 * contact temperature and the lag jump there.  So regime k (k = 0 ... NREG-1) between the
 * edges e_k and e_k+1 (e_0 = 0, e_NREG = U_MAX) has its own tables over
 *     xi = k + (u - e_k)/(e_k+1 - e_k)   and   s = -ln(nu(T_sump)/(1 mm^2/s)),
 * the edges and s from AXIS_TABLE over T_sump.
 *
 * Steady maps (sealsim.rotary.simulation.steady_state with the sump held at T_sump, ambient
 * T_ambient_map): the contact temperature rise above the sump dT_ss and its sensitivity to
 * the ambient temperature, d dT_ss / d T_ambient (STEADY_MAPS[k]).
 *
 * Thermal lag (identified from step responses of the transient model,
 * sealsim.fmu.rotary_maps): the rise is the sum of NLAG first-order components and the
 * contact follows the sump through the slowest of them:
 *     d x_i/dt = (a_i r - x_i)/tau_i,   d s/dt = (T_sump - s)/tau_NLAG,
 *     T_contact = s + sum x_i,   r = dT_ss + (d dT_ss/d T_ambient) (T_ambient - T_ambient_map);
 * a_i and log tau_i interpolated bilinearly over (xi, s) between the identified points of
 * the regime (LAG_XI[LAG_START[k] ... LAG_START[k+1]-1] x LAG_S), constant beyond them.
 * In a communication step the inputs are held and the update is exact:
 *     x(t+h) = x_ss + (x - x_ss) exp(-h/tau).
 *
 * Friction torque (sealsim.rotary.friction via friction_map): torque(|speed|, T_contact) from
 * a table; below TORQUE_SPEED_MIN it ramps linearly to 0 at standstill (sealsim's model gives
 * 0 at rest; the ramp keeps the torque continuous for the host's solver).  Power loss
 * P = torque |speed|.
 *
 * Above the table's top speed every output belongs to one operating point, the top speed
 * (torque, T_contact, T_contact_steady and P = torque x top speed), flagged by map_clipped
 * and the log.  Why not torque x the real speed: that power would belong to no operating
 * point (its heat is not the heat of the contact temperatures reported with it).  Why not
 * refuse: the other inputs (sump, ambient) are clipped the same way, and a host that runs
 * briefly over the table keeps running with the flag set instead of stopping. */
#include "sealsim_fmu.h"

#define P(name) (c->r[VR_##name])
#define CLIP_SPEED 1u
#define CLIP_SUMP 2u
#define CLIP_AMBIENT 4u
#define CLIP_CONTACT 8u

static double speed_coordinate(double speed) {
    return log1p(fabs(speed) / SPEED_SCALE);
}

/* where the current (clipped) inputs lie in the maps */
typedef struct {
    int regime;
    double xi, s;
} MapPoint;

static MapPoint map_point(Instance *c) {
    MapPoint m;
    double axis[NREG], edges[NREG + 1];
    double omega = fmu_clip(c, CLIP_SPEED, "shaft speed |speed|", "rad/s", fabs(P(SPEED)),
                            0.0, STEADY_SPEED_HI);
    double sump = fmu_clip(c, CLIP_SUMP, "sump temperature T_sump", "K", P(T_SUMP),
                           STEADY_SUMP_LO, STEADY_SUMP_HI);
    double u = speed_coordinate(omega);
    hermite_evaluate(&AXIS_TABLE, sump, 0.0, axis);
    m.s = axis[0];
    edges[0] = 0.0;
    for (int k = 1; k < NREG; k++) edges[k] = axis[k];
    edges[NREG] = U_MAX;
    m.regime = 0;
    while (m.regime < NREG - 1 && u >= edges[m.regime + 1]) m.regime++;
    m.xi = m.regime + (u - edges[m.regime]) / (edges[m.regime + 1] - edges[m.regime]);
    return m;
}

/* steady rise of the contact temperature above the sump at the current inputs [K] */
static double steady_rise(Instance *c, const MapPoint *m) {
    double values[2];
    double ambient = fmu_clip(c, CLIP_AMBIENT, "ambient temperature T_ambient", "K",
                              P(T_AMBIENT), AMBIENT_LO, AMBIENT_HI);
    hermite_evaluate(STEADY_MAPS[m->regime], m->xi, m->s, values);
    return values[0] + values[1] * (ambient - AMBIENT_MAP);
}

/* position of x in the ascending nodes (clamped): cell j and fraction t */
static void locate(const double *nodes, int n, double x, int *j, double *t) {
    *j = 0;
    *t = 0.0;
    if (n < 2) return;
    if (x <= nodes[0]) return;
    if (x >= nodes[n - 1]) {
        *j = n - 2;
        *t = 1.0;
        return;
    }
    while (*j < n - 2 && x > nodes[*j + 1]) (*j)++;
    *t = (x - nodes[*j]) / (nodes[*j + 1] - nodes[*j]);
}

/* weights a_i and time constants tau_i [s] at a point of the maps */
static void lag_parameters(const MapPoint *m, double *weight, double *tau) {
    int j, k;
    double t, s;
    int first = LAG_START[m->regime], n = LAG_START[m->regime + 1] - first;
    locate(LAG_XI + first, n, m->xi, &j, &t);
    locate(LAG_S, LAG_NT, m->s, &k, &s);
    int j0 = first + j, j1 = first + (n > 1 ? j + 1 : j), k1 = LAG_NT > 1 ? k + 1 : k;
    double w00 = (1.0 - t) * (1.0 - s), w10 = t * (1.0 - s), w01 = (1.0 - t) * s, w11 = t * s;
    for (int i = 0; i < NLAG; i++) {
#define LAG_AT(table, a, b) table[((a) * LAG_NT + (b)) * NLAG + i]
#define BILINEAR(table) (w00 * LAG_AT(table, j0, k) + w10 * LAG_AT(table, j1, k) + \
                         w01 * LAG_AT(table, j0, k1) + w11 * LAG_AT(table, j1, k1))
        weight[i] = BILINEAR(LAG_WEIGHT);
        tau[i] = exp(BILINEAR(LAG_LOG_TAU));
#undef BILINEAR
#undef LAG_AT
    }
}

static double contact_temperature(Instance *c) {
    double sum = P(SUMP_LAG);
    for (int i = 0; i < NLAG; i++) sum += c->r[STATE_VR[i]];
    return sum;
}

/* steady values and time constants of the rise components and the lagged sump */
static void lag_targets(Instance *c, double *target, double *tau) {
    double weight[NLAG];
    MapPoint m = map_point(c);
    double rise = steady_rise(c, &m);
    lag_parameters(&m, weight, tau);
    for (int i = 0; i < NLAG; i++) target[i] = weight[i] * rise;
    target[NLAG] = P(T_SUMP);
    tau[NLAG] = tau[NLAG - 1];
}

static double *lag_state(Instance *c, int i) {
    return i < NLAG ? &c->r[STATE_VR[i]] : &P(SUMP_LAG);
}

FmuStatus model_check_parameters(Instance *c) {
    (void)c;
    return FMU_OK;
}

FmuStatus model_initialize(Instance *c) {
    double target[NLAG + 1], tau[NLAG + 1];
    lag_targets(c, target, tau);
    for (int i = 0; i <= NLAG; i++) {
        /* in steady state at the inputs, or in equilibrium at T_contact_start */
        *lag_state(c, i) = P(START_STEADY) != 0.0 ? target[i]
                           : (i < NLAG ? 0.0 : P(T_CONTACT_START));
        c->nominals[i] = i < NLAG ? 10.0 : 300.0;
    }
    return FMU_OK;
}

FmuStatus model_outputs(Instance *c) {
    double speed = P(SPEED);
    double t_contact = contact_temperature(c);
    double t_table = fmu_clip(c, CLIP_CONTACT, "contact temperature", "K", t_contact,
                              TORQUE_TC_LO, TORQUE_TC_HI);
    double torque;
    MapPoint m = map_point(c);
    /* above the table the speed is clipped (and reported) in map_point: all outputs, the
     * power too, are those of the top speed (see the head of this file) */
    double omega = fmin(fabs(speed), STEADY_SPEED_HI);
    double u = speed_coordinate(omega < TORQUE_SPEED_MIN ? TORQUE_SPEED_MIN : omega);
    hermite_evaluate(&TORQUE_MAP, u, t_table, &torque);
    if (omega < TORQUE_SPEED_MIN) torque *= omega / TORQUE_SPEED_MIN;
    P(T_CONTACT_STEADY) = P(T_SUMP) + steady_rise(c, &m);
    P(TORQUE) = speed >= 0.0 ? torque : -torque;
    P(POWER) = torque * omega;
    P(T_CONTACT) = t_contact;
    P(MAP_CLIPPED) = c->clipping != 0u ? 1.0 : 0.0;
    if (!isfinite(P(TORQUE)) || !isfinite(P(T_CONTACT)) || !isfinite(P(T_CONTACT_STEADY))) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "the outputs are not finite (speed = %g rad/s, T_sump = %g K)", speed,
                P(T_SUMP));
        return FMU_ERROR;
    }
    return FMU_OK;
}

void model_derivatives(Instance *c, double *dx) {
    double target[NLAG + 1], tau[NLAG + 1];
    lag_targets(c, target, tau);
    for (int i = 0; i <= NLAG; i++) dx[i] = (target[i] - *lag_state(c, i)) / tau[i];
}

FmuStatus model_step(Instance *c, double h) {
    double target[NLAG + 1], tau[NLAG + 1];
    lag_targets(c, target, tau);
    for (int i = 0; i <= NLAG; i++) {
        double *x = lag_state(c, i);
        *x = target[i] + (*x - target[i]) * exp(-h / tau[i]);
    }
    return FMU_OK;
}
