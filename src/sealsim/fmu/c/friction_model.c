/* Seal friction: the friction laws of sealsim.friction in C, one law per FMU (FRICTION_LAW).
 *
 * Sign convention (sealsim.friction.base): v is the sliding velocity of the body relative
 * to the seal, F acts against the body (m dv/dt = F_applied - F).  Every formula is the
 * compiled scalar kernel of sealsim.friction.kernels named next to it (same equations, same
 * argument order; tests compare them over random inputs); the states advance with the exact
 * update of sealsim's law.step() for inputs held over the step, so a communication step of
 * any length is stable (stiff bristles, long dwells).
 *
 * Contact: F_N and b from the contact table (CONTACT_TABLE) at the pressure difference
 * across the seal dp = x tanh(x/eps), x = p_A - p_B (sealsim.pneumatic.seals.smooth_abs),
 * and the seal temperature; or the constant parameters normal_force, contact_width.
 *
 * The Theta law with steady = "contact" (THETA_CONTACT) takes its steady curve from the
 * seal's friction table FRIC_ROW/FRIC_DATA (contact_table.c) at dp and T_seal: F_ss(v) =
 * pi D [mu_b L + V] in the table direction of v times the orientation
 * velocity_direction * (p_A >= p_B ? 1 : -1) (velocity_direction +1: a positive v slides the
 * counter surface from side A to side B of the seal; the table's "+" is from the pressurised
 * side to the other), and the level F_ss(|v|) + dF (theta_ss(v) - theta), at rest
 * F_ss(0+) (1 - d theta), dF = d pi D mu_b L: the dwell drop d of the boundary part at the
 * film's speed (sealsim.friction.theta, Theta.level).  The asperity
 * load L is read at the speed phi the contact's film has formed for, the law's last state
 * film_speed: dphi/dt = (|v| - phi)(|v|/b + kappa) (kernels.film_speed_rate, kappa the
 * film's decay rate at rest from the table: Reynolds' squeeze film), so F_ss depends
 * on a state and is computed at each evaluation, not cached with the inputs. */
#include "sealsim_fmu.h"

#define LAW_COULOMB 1
#define LAW_STRIBECK 2
#define LAW_LUGRE 3
#define LAW_THETA 4

#define P(name) (c->r[VR_##name])
#define CLIP_PRESSURE 1u
#define CLIP_TEMPERATURE 2u

static double sgn(double x) {
    return (double)((x > 0.0) - (x < 0.0));  /* numpy.sign: sgn(0) = 0 */
}

typedef struct {
    double v, normal_force, contact_width, dp;
    double gamma;      /* viscous coefficient of the Theta law at T_seal [N s/m^2] */
    double orient;     /* THETA_CONTACT: the friction table's direction of a positive v */
} Contact;

static double viscous_coefficient(Instance *c);

/* the contact at the current inputs, cached until an input or a parameter is set */
static Contact contact(Instance *c) {
    Contact k;
    if (c->cache_valid) {
        k.v = c->cache[0];
        k.normal_force = c->cache[1];
        k.contact_width = c->cache[2];
        k.dp = c->cache[3];
        k.gamma = c->cache[4];
        k.orient = c->cache[5];
        return k;
    }
    double x = P(P_A) - P(P_B);
    k.v = P(V);
    k.dp = x * tanh(x / P(PRESSURE_ROUNDING));
#if CONTACT_TABLE
    double values[2];
    double dp = fmu_clip(c, CLIP_PRESSURE, "pressure difference dp", "Pa", k.dp, MAP_P_LO,
                         MAP_P_HI);
    double temperature = fmu_clip(c, CLIP_TEMPERATURE, "seal temperature T_seal", "K",
                                  P(T_SEAL), MAP_T_LO, MAP_T_HI);
    hermite_evaluate(&CONTACT_MAP, temperature, dp, values);
    k.normal_force = values[0];
    k.contact_width = values[1];
#else
    k.normal_force = P(NORMAL_FORCE);
    k.contact_width = P(CONTACT_WIDTH);
#endif
    c->cache[0] = k.v;
    c->cache[1] = k.normal_force;
    c->cache[2] = k.contact_width;
    k.gamma = viscous_coefficient(c);
    c->cache[3] = k.dp;
    c->cache[4] = k.gamma;
    k.orient = 0.0;
#if FRICTION_LAW == LAW_THETA && THETA_CONTACT
    k.orient = P(VELOCITY_DIRECTION) * (P(P_A) >= P(P_B) ? 1.0 : -1.0);
#endif
    c->cache[5] = k.orient;
    c->cache_valid = 1;
    return k;
}

/* -- Stribeck curve and pressure scaling (sealsim.friction.stribeck) --------------------- */
#if FRICTION_LAW == LAW_COULOMB || FRICTION_LAW == LAW_STRIBECK
/* pressure_scaled_force: F_C(p) = F_C + f (p_A + p_B);
 * stribeck_scaled_levels: F_S(p) = F_S F_C(p)/F_C, or F_S + (F_C(p) - F_C) when F_C = 0 */
static void scaled_levels(Instance *c, double *fc, double *fs) {
    double fc0 = P(COULOMB_FORCE);
    double scaled = fc0 + P(PRESSURE_COEFFICIENT) * (P(P_A) + P(P_B));
    *fc = scaled;
#if FRICTION_LAW == LAW_STRIBECK
    double fs0 = P(STATIC_FORCE);
    *fs = fc0 > 0.0 ? fs0 * scaled / fc0 : fs0 + (scaled - fc0);
#else
    *fs = scaled;
#endif
}
#endif

#if FRICTION_LAW == LAW_STRIBECK || FRICTION_LAW == LAW_LUGRE
/* stribeck_level: g(v) = F_C + (F_S - F_C) exp(-|v/v_S|^delta) */
static double stribeck_level(double v, double fc, double fs, double vs, double delta) {
    return fc + (fs - fc) * exp(-pow(fabs(v / vs), delta));
}
#endif

/* -- LuGre bristle (sealsim.friction.lugre) -------------------------------------------------- */
#if FRICTION_LAW == LAW_LUGRE || (FRICTION_LAW == LAW_THETA && THETA_BRISTLES)
/* lugre_bristle_rate: dz/dt = v - sigma0 |v| z / g */
static double bristle_rate(double z, double v, double sigma0, double g) {
    return v - sigma0 * fabs(v) * z / g;
}

/* lugre_affine: z(t+h) = z_ss + (z - z_ss) exp(-sigma0 |v| h / g), z_ss = sgn(v) g/sigma0 */
static double bristle_step(double z, double v, double h, double sigma0, double g) {
    double decay = -expm1(-sigma0 * fabs(v) * h / g);
    double z_ss = sgn(v) * g / sigma0;
    return (1.0 - decay) * z + z_ss * decay;
}
#endif

/* -- Theta rate-and-state law (sealsim.friction.theta) --------------------------------------- */
#if FRICTION_LAW == LAW_THETA
/* theta_load_factor: (F_N/F_ref)^n */
static double load_factor(Instance *c, double normal_force) {
    return pow(normal_force / P(REFERENCE_NORMAL_FORCE), P(LOAD_EXPONENT));
}

#if THETA_CONTACT
/* theta_steady: theta_ss = |v|/(|v| + v*), v* = alpha/tau (F_N/F_ref)^n */
static double theta_steady(Instance *c, const Contact *k) {
    double speed = fabs(k->v);
    if (speed > 0.0)
        return speed / (speed + P(ALPHA) / P(TAU) * load_factor(c, k->normal_force));
    return 0.0;
}
#endif

/* the friction level at theta: theta_friction_level g = F_N [f_a (1 - theta) + f_b theta],
 * or on the contact table theta_contact_level (compiled._theta_level) at the contact's v
 * with the film formed for the speed film [m/s] (compiled.contact_steady; unused without
 * the table) */
static double theta_level(Instance *c, double theta, double film, const Contact *k) {
#if THETA_CONTACT
    double steady, boundary, viscous, unused;
    contact_steady(FRIC_ROW, FRIC_DATA, P(T_SEAL), k->dp, k->orient * k->v, film,
                   3.141592653589793 * P(SLIDING_DIAMETER), P(BOUNDARY_FRICTION), &steady,
                   &boundary, &viscous, &unused);
    return theta_contact_level(theta, k->v, steady, boundary, P(DWELL_DROP),
                               theta_steady(c, k), viscous);
#else
    (void)film;
    return k->normal_force * (P(F_A) * (1.0 - theta) + P(F_B) * theta);
#endif
}

#if THETA_CONTACT
/* the decay rate [1/s] of the film formed for the speed film (compiled.contact_steady's) */
static double film_decay(Instance *c, double film, const Contact *k) {
    return film_decay_rate(FRIC_ROW, FRIC_DATA, P(T_SEAL), k->dp, film);
}
#endif

/* the level at rest (the break-away force; the asperities carry the load the film leaves) */
static double theta_rest_level(Instance *c, double theta, double film, const Contact *k) {
    Contact rest = *k;
    rest.v = 0.0;
    return theta_level(c, theta, film, &rest);
}


/* theta_rate: dtheta/dt = -theta/tau + |v|/(alpha (F_N/F_ref)^n) (1 - theta) */
static double theta_rate(Instance *c, double theta, const Contact *k) {
    double p = load_factor(c, k->normal_force);
    return -theta / P(TAU) + fabs(k->v) / (P(ALPHA) * p) * (1.0 - theta);
}

/* theta_affine: exact theta after h with v and F_N held (theta_steady: |v|/(|v| + v*)) */
static double theta_step(Instance *c, double theta, const Contact *k, double h) {
    double speed = fabs(k->v), tau = P(TAU), alpha = P(ALPHA);
    double p = load_factor(c, k->normal_force);
    double r = speed > 0.0 ? (p > 0.0 ? speed / (alpha * p) : INFINITY) : 0.0;
    double decay = -expm1(-(1.0 / tau + r) * h);
    double v_star = alpha / tau * p;
    double theta_ss = speed > 0.0 ? speed / (speed + v_star) : 0.0;
    return (1.0 - decay) * theta + theta_ss * decay;
}
#endif

/* The viscous coefficient gamma [N s/m^2] of F = ... + gamma b v: constant, or with
 * THETA_VISCOSITY gamma(T) = gamma nu(T)/nu(T_ref) (Theta.gamma, theta_viscous_coefficient)
 * with the base oil's ASTM D341 (Walther) viscosity log10 log10(nu + 0.7) = A - B log10 T
 * (nu in mm^2/s, T in K) through its datasheet viscosities at 40 and 100 degC
 * (sealsim.properties.oils.walther_constants). */
#if FRICTION_LAW == LAW_THETA && THETA_VISCOSITY
#define WALTHER_T40 313.15
#define WALTHER_T100 373.15

/* W = log10 log10(nu + 0.7), nu in mm^2/s (the argument in m^2/s) */
static double walther_w(double nu) {
    return log10(log10(nu * 1e6 + 0.7));
}

/* walther_viscosity_ratio: nu(T)/nu(T_ref), nu = 10^(10^(A - B log10 T)) - 0.7 */
static double walther_viscosity_ratio(double t, double tref, double wa, double wb) {
    double nu = pow(10.0, pow(10.0, wa - wb * log10(t))) - 0.7;
    double nu_ref = pow(10.0, pow(10.0, wa - wb * log10(tref))) - 0.7;
    return nu / nu_ref;
}
#endif

static double viscous_coefficient(Instance *c) {
#if FRICTION_LAW == LAW_THETA && THETA_CONTACT
    (void)c;
    return 0.0;                 /* the table holds the viscous friction */
#elif FRICTION_LAW == LAW_THETA && THETA_VISCOSITY
    double w40 = walther_w(P(BASE_OIL_NU40)), w100 = walther_w(P(BASE_OIL_NU100));
    double wb = (w40 - w100) / (log10(WALTHER_T100) - log10(WALTHER_T40));
    double wa = w40 + wb * log10(WALTHER_T40);
    return P(GAMMA) * walther_viscosity_ratio(P(T_SEAL), P(REFERENCE_TEMPERATURE), wa, wb);
#elif FRICTION_LAW == LAW_THETA
    return P(GAMMA);
#else
    (void)c;
    return 0.0;
#endif
}

/* -- the model interface ---------------------------------------------------------------------- */
FmuStatus model_check_parameters(Instance *c) {
#if FRICTION_LAW == LAW_STRIBECK || FRICTION_LAW == LAW_LUGRE
    if (P(STATIC_FORCE) < P(COULOMB_FORCE)) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "static_force (%g N) must be >= coulomb_force (%g N)", P(STATIC_FORCE),
                P(COULOMB_FORCE));
        return FMU_ERROR;
    }
#endif
#if FRICTION_LAW == LAW_THETA && THETA_VISCOSITY
    /* ThetaParameters and walther_constants: the double logarithm exists above 0.3 mm^2/s */
    if (!(P(BASE_OIL_NU100) > 0.3e-6)) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "base_oil_nu100 (%g m2/s) must be > 0.3e-6 m2/s (0.3 mm2/s, ASTM D341)",
                P(BASE_OIL_NU100));
        return FMU_ERROR;
    }
    if (!(P(BASE_OIL_NU40) > P(BASE_OIL_NU100))) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "base_oil_nu40 (%g m2/s) must be larger than base_oil_nu100 (%g m2/s): an oil "
                "thins when it is heated", P(BASE_OIL_NU40), P(BASE_OIL_NU100));
        return FMU_ERROR;
    }
#endif
#if FRICTION_LAW == LAW_THETA && !THETA_CONTACT
    /* ThetaParameters: f_a is the dry level (theta = 0, the break-away force after a long
     * dwell), f_b the full-film one; f_b > f_a would break away below the sliding level */
    if (P(F_B) > P(F_A)) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "parameter f_b = %g is larger than f_a = %g: f_b (the full-film friction "
                "coefficient, theta = 1) must be <= f_a (the dry one, theta = 0, the "
                "break-away level after a long dwell)", P(F_B), P(F_A));
        return FMU_ERROR;
    }
#endif
#if FRICTION_LAW == LAW_THETA && THETA_BRISTLES && !THETA_CONTACT
    if (P(F_A) <= 0.0 || P(F_B) <= 0.0) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "with bristle_stiffness the friction coefficients f_a and f_b must be > 0 "
                "(the bristles saturate at F_N*f), got f_a = %g, f_b = %g", P(F_A), P(F_B));
        return FMU_ERROR;
    }
#endif
    (void)c;
    return FMU_OK;
}

FmuStatus model_initialize(Instance *c) {
#if FRICTION_LAW == LAW_THETA
    if (P(THETA) < 0.0 || P(THETA) > 1.0) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "the start value of theta (%g) must lie in [0, 1]", P(THETA));
        return FMU_ERROR;
    }
    c->nominals[STATE_THETA] = 1.0;
#endif
#if FRICTION_LAW == LAW_THETA && THETA_CONTACT
    if (!(P(FILM_SPEED) >= 0.0)) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "the start value of film_speed (%g m/s), the speed the contact's film has "
                "formed for, must be >= 0 m/s", P(FILM_SPEED));
        return FMU_ERROR;
    }
#endif
#if FRICTION_LAW == LAW_LUGRE
    c->nominals[STATE_Z] = P(STATIC_FORCE) / P(SIGMA0);
#endif
#if FRICTION_LAW == LAW_THETA && THETA_BRISTLES
    {
        Contact k = contact(c);
        double z_scale = theta_rest_level(c, 0.0, P(FILM_SPEED), &k) / P(BRISTLE_STIFFNESS);
        c->nominals[STATE_Z] = z_scale > 0.0 ? z_scale : 1e-6;
    }
#endif
    (void)c;
    return FMU_OK;
}

FmuStatus model_outputs(Instance *c) {
    Contact k = contact(c);
    double force = 0.0, breakaway = 0.0;
#if FRICTION_LAW == LAW_THETA || CONTACT_TABLE
    if (!(k.normal_force > 0.0) || !(k.contact_width >= 0.0)) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "contact: normal force %g N must be > 0 and contact width %g m >= 0",
                k.normal_force, k.contact_width);
        return FMU_ERROR;
    }
#endif
#if FRICTION_LAW == LAW_COULOMB
    double fc, fs;
    scaled_levels(c, &fc, &fs);
    force = fc * sgn(k.v) + P(VISCOUS_COEFFICIENT) * k.v;     /* coulomb_viscous_force */
    breakaway = fs;
#elif FRICTION_LAW == LAW_STRIBECK
    double fc, fs;
    scaled_levels(c, &fc, &fs);
    force = stribeck_level(k.v, fc, fs, P(STRIBECK_VELOCITY), P(EXPONENT)) * sgn(k.v) +
            P(VISCOUS_COEFFICIENT) * k.v;                       /* stribeck_force */
    breakaway = fs;
#elif FRICTION_LAW == LAW_LUGRE
    double g = stribeck_level(k.v, P(COULOMB_FORCE), P(STATIC_FORCE), P(STRIBECK_VELOCITY),
                              P(EXPONENT));
    double zdot = bristle_rate(P(Z), k.v, P(SIGMA0), g);
    force = P(SIGMA0) * P(Z) + P(SIGMA1) * zdot + P(SIGMA2) * k.v;   /* lugre_force */
#elif FRICTION_LAW == LAW_THETA
    double level = theta_level(c, P(THETA), P(FILM_SPEED), &k);
    double gamma = k.gamma;
#if THETA_VISCOSITY
    if (!(P(T_SEAL) > 0.0)) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "seal temperature T_seal = %g K must be > 0 K (gamma(T) of the base oil)",
                P(T_SEAL));
        return FMU_ERROR;
    }
#endif
#if THETA_BRISTLES
    double zdot = bristle_rate(P(Z), k.v, P(BRISTLE_STIFFNESS), level);
    force = P(BRISTLE_STIFFNESS) * P(Z) + P(BRISTLE_DAMPING) * zdot +
            gamma * k.contact_width * k.v;
#elif THETA_CONTACT
    force = level * sgn(k.v);                                      /* Theta.force */
    breakaway = theta_rest_level(c, P(THETA), P(FILM_SPEED), &k);
#else
    force = level * sgn(k.v) + gamma * k.contact_width * k.v;      /* theta_force */
    breakaway = level;
#endif
#endif
    if (!isfinite(force) || !isfinite(breakaway)) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "the friction force is not finite (v = %g m/s, F_N = %g N, b = %g m)", k.v,
                k.normal_force, k.contact_width);
        return FMU_ERROR;
    }
    P(F) = force;
    P(F_BREAKAWAY) = breakaway;
    P(F_N) = k.normal_force;
    P(B) = k.contact_width;
    P(DP) = k.dp;
    P(MAP_CLIPPED) = c->clipping != 0u ? 1.0 : 0.0;
    return FMU_OK;
}

void model_derivatives(Instance *c, double *dx) {
#if NSTATES > 0
    Contact k = contact(c);
#if FRICTION_LAW == LAW_LUGRE
    double g = stribeck_level(k.v, P(COULOMB_FORCE), P(STATIC_FORCE), P(STRIBECK_VELOCITY),
                              P(EXPONENT));
    dx[STATE_Z] = bristle_rate(P(Z), k.v, P(SIGMA0), g);
#elif FRICTION_LAW == LAW_THETA
    dx[STATE_THETA] = theta_rate(c, P(THETA), &k);
#if THETA_BRISTLES
    dx[STATE_Z] = bristle_rate(P(Z), k.v, P(BRISTLE_STIFFNESS),
                               theta_level(c, P(THETA), P(FILM_SPEED), &k));
#endif
#if THETA_CONTACT
    dx[STATE_FILM_SPEED] = film_speed_rate(P(FILM_SPEED), k.v, k.contact_width,
                                           film_decay(c, P(FILM_SPEED), &k));
#endif
#endif
#else
    (void)c;
    (void)dx;
#endif
}

FmuStatus model_step(Instance *c, double h) {
#if NSTATES > 0
    Contact k = contact(c);
#if FRICTION_LAW == LAW_LUGRE
    double g = stribeck_level(k.v, P(COULOMB_FORCE), P(STATIC_FORCE), P(STRIBECK_VELOCITY),
                              P(EXPONENT));
    P(Z) = bristle_step(P(Z), k.v, h, P(SIGMA0), g);
#elif FRICTION_LAW == LAW_THETA
    double theta0 = P(THETA);
    double theta1 = theta_step(c, theta0, &k, h);
    double film_mid = P(FILM_SPEED);
#if THETA_CONTACT
    /* the film's speed: film_speed_affine, exact for v, b and the film's decay rate held
     * (frozen at the step's start: Theta.step) */
    double a, b;
    film_speed_affine(k.v, h, k.contact_width, film_decay(c, P(FILM_SPEED), &k), &a, &b);
    double film1 = a * P(FILM_SPEED) + b;
    film_mid = 0.5 * (P(FILM_SPEED) + film1);
#endif
#if THETA_BRISTLES
    /* the bristle step with the friction level of the step's mid-state (Theta.step) */
    double g_mid = theta_level(c, 0.5 * (theta0 + theta1), film_mid, &k);
    P(Z) = bristle_step(P(Z), k.v, h, P(BRISTLE_STIFFNESS), g_mid);
#endif
    (void)film_mid;
    P(THETA) = theta1;
#if THETA_CONTACT
    P(FILM_SPEED) = film1;
#endif
#endif
#else
    (void)c;
    (void)h;
#endif
    return FMU_OK;
}
