/* sealsim FMU runtime: variables, life cycle, parameter checks, logging, clipping.
 * Independent of the FMI version; the glue files map the FMI API onto these functions. */
#include "sealsim_fmu.h"

void fmu_log(Instance *c, FmuStatus status, const char *category, const char *format, ...) {
    char message[1024];
    va_list args;
    if (c == NULL || c->logger == NULL) return;
    /* debug messages only when the host asked for logging; warnings and errors always */
    if (status == FMU_OK && !c->logging_on) return;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    glue_log(c, status, category, message);
}

static void set_start_values(Instance *c) {
    memcpy(c->r, START_VALUES, sizeof c->r);
    c->time = 0.0;
    c->clipping = 0u;
    c->outputs_valid = 0;
    c->cache_valid = 0;
    for (int i = 0; i < STATE_ARRAY_SIZE; i++) c->nominals[i] = 1.0;
}

Instance *fmu_instantiate(const char *name, int cosimulation, int logging_on,
                          void *environment, void (*logger)(void)) {
    Instance *c = (Instance *)calloc(1, sizeof(Instance));
    if (c == NULL) return NULL;
    snprintf(c->instance_name, sizeof c->instance_name, "%s", name ? name : "");
    c->cosimulation = cosimulation;
    c->logging_on = logging_on;
    c->environment = environment;
    c->logger = logger;
    c->phase = PHASE_INSTANTIATED;
    set_start_values(c);
    return c;
}

void fmu_free(Instance *c) {
    free(c);
}

void fmu_reset(Instance *c) {
    set_start_values(c);
    c->phase = PHASE_INSTANTIATED;
}

static int valid_vr(Instance *c, unsigned vr, const char *function) {
    if (vr >= NVARS || VARIABLES[vr].name == NULL) {
        fmu_log(c, FMU_ERROR, "logStatusError", "%s: unknown value reference %u", function, vr);
        return 0;
    }
    return 1;
}

static FmuStatus fail(Instance *c) {
    c->phase = PHASE_ERROR;
    return FMU_ERROR;
}

static FmuStatus update_outputs(Instance *c) {
    if (c->outputs_valid) return FMU_OK;
    FmuStatus status = model_outputs(c);
    if (status > FMU_WARNING) return status;
    c->outputs_valid = 1;
    return status;
}

FmuStatus fmu_get_real(Instance *c, const unsigned *vr, size_t n, double *value) {
    if (c->phase == PHASE_ERROR) return FMU_ERROR;
    if (n > 0 && update_outputs(c) > FMU_WARNING) return fail(c);
    for (size_t k = 0; k < n; k++) {
        if (!valid_vr(c, vr[k], "get real")) return FMU_ERROR;
        value[k] = vr[k] == VR_TIME ? c->time : c->r[vr[k]];
    }
    return FMU_OK;
}

FmuStatus fmu_get_boolean(Instance *c, const unsigned *vr, size_t n, int *value) {
    if (c->phase == PHASE_ERROR) return FMU_ERROR;
    if (n > 0 && update_outputs(c) > FMU_WARNING) return fail(c);
    for (size_t k = 0; k < n; k++) {
        if (!valid_vr(c, vr[k], "get boolean")) return FMU_ERROR;
        if (!VARIABLES[vr[k]].is_boolean) {
            fmu_log(c, FMU_ERROR, "logStatusError", "get boolean: %s is not a Boolean",
                    VARIABLES[vr[k]].name);
            return FMU_ERROR;
        }
        value[k] = c->r[vr[k]] != 0.0;
    }
    return FMU_OK;
}

/* may vr be set now?  inputs until the end, parameters and start values of states only
 * before the end of initialization */
static int settable(Instance *c, unsigned vr) {
    const VariableInfo *v = &VARIABLES[vr];
    if (c->phase == PHASE_TERMINATED || c->phase == PHASE_ERROR) {
        fmu_log(c, FMU_ERROR, "logStatusError", "cannot set %s: the instance is %s", v->name,
                c->phase == PHASE_ERROR ? "in an error state" : "terminated");
        return 0;
    }
    if (v->settable == SET_ALWAYS) return 1;
    if (v->settable == SET_BEFORE_INIT) {
        if (c->phase <= PHASE_INITIALIZATION) return 1;
        fmu_log(c, FMU_ERROR, "logStatusError",
                "%s is fixed: set it before the end of initialization", v->name);
        return 0;
    }
    fmu_log(c, FMU_ERROR, "logStatusError", "%s cannot be set (it is computed by the model)",
            v->name);
    return 0;
}

static const char *bound_text(int kind, int lower) {
    if (kind == BOUND_INCLUSIVE) return lower ? ">=" : "<=";
    return lower ? ">" : "<";
}

/* is x outside the bounds of v?  *low: the lower bound is the one violated */
static int outside_bounds(const VariableInfo *v, double x, int *low) {
    *low = (v->lower_kind == BOUND_INCLUSIVE && !(x >= v->lower)) ||
           (v->lower_kind == BOUND_EXCLUSIVE && !(x > v->lower));
    int high = (v->upper_kind == BOUND_INCLUSIVE && !(x <= v->upper)) ||
               (v->upper_kind == BOUND_EXCLUSIVE && !(x < v->upper));
    return *low || high;
}

FmuStatus fmu_set_real(Instance *c, const unsigned *vr, size_t n, const double *value) {
    for (size_t k = 0; k < n; k++) {
        if (!valid_vr(c, vr[k], "set real") || !settable(c, vr[k])) return FMU_ERROR;
        if (VARIABLES[vr[k]].is_boolean) {
            fmu_log(c, FMU_ERROR, "logStatusError", "set real: %s is a Boolean",
                    VARIABLES[vr[k]].name);
            return FMU_ERROR;
        }
        if (!isfinite(value[k])) {
            fmu_log(c, FMU_ERROR, "logStatusError",
                    "%s = %g is not allowed: the value must be finite (it was not set)",
                    VARIABLES[vr[k]].name, value[k]);
            return FMU_ERROR;
        }
        /* an input outside its bounds (a gauge pressure below vacuum) has no meaning: refused
         * when it is set (parameters are checked at the end of initialization) */
        const VariableInfo *v = &VARIABLES[vr[k]];
        int low;
        if (v->causality == CAUSALITY_INPUT && outside_bounds(v, value[k], &low)) {
            fmu_log(c, FMU_ERROR, "logStatusError",
                    "input %s = %g %s is not allowed: it must be %s %g %s (it was not set)",
                    v->name, value[k], v->unit, bound_text(low ? v->lower_kind : v->upper_kind,
                                                           low),
                    low ? v->lower : v->upper, v->unit);
            return FMU_ERROR;
        }
        c->r[vr[k]] = value[k];
    }
    if (n > 0) c->outputs_valid = c->cache_valid = 0;
    return FMU_OK;
}

FmuStatus fmu_set_boolean(Instance *c, const unsigned *vr, size_t n, const int *value) {
    for (size_t k = 0; k < n; k++) {
        if (!valid_vr(c, vr[k], "set boolean") || !settable(c, vr[k])) return FMU_ERROR;
        if (!VARIABLES[vr[k]].is_boolean) {
            fmu_log(c, FMU_ERROR, "logStatusError", "set boolean: %s is not a Boolean",
                    VARIABLES[vr[k]].name);
            return FMU_ERROR;
        }
        c->r[vr[k]] = value[k] ? 1.0 : 0.0;
    }
    if (n > 0) c->outputs_valid = c->cache_valid = 0;
    return FMU_OK;
}

/* every parameter within its bounds (those of sealsim's case-file models) */
static FmuStatus check_bounds(Instance *c) {
    FmuStatus status = FMU_OK;
    for (unsigned vr = 0; vr < NVARS; vr++) {
        const VariableInfo *v = &VARIABLES[vr];
        if (v->name == NULL || v->causality != CAUSALITY_PARAMETER) continue;
        double x = c->r[vr];
        int low;
        if (outside_bounds(v, x, &low)) {
            fmu_log(c, FMU_ERROR, "logStatusError",
                    "parameter %s = %g %s is not allowed: it must be %s %g %s", v->name, x,
                    v->unit, bound_text(low ? v->lower_kind : v->upper_kind, low),
                    low ? v->lower : v->upper, v->unit);
            status = FMU_ERROR;
        }
    }
    return status;
}

FmuStatus fmu_enter_initialization(Instance *c) {
    if (c->phase != PHASE_INSTANTIATED) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "enter initialization mode: only allowed after instantiation or reset");
        return FMU_ERROR;
    }
    c->phase = PHASE_INITIALIZATION;
    return FMU_OK;
}

FmuStatus fmu_exit_initialization(Instance *c) {
    if (c->phase != PHASE_INITIALIZATION) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "exit initialization mode: not in initialization mode");
        return FMU_ERROR;
    }
    if (check_bounds(c) > FMU_WARNING || model_check_parameters(c) > FMU_WARNING ||
        model_initialize(c) > FMU_WARNING) {
        return fail(c);
    }
    c->outputs_valid = 0;
    if (update_outputs(c) > FMU_WARNING) return fail(c);
    c->phase = PHASE_RUNNING;
    return FMU_OK;
}

FmuStatus fmu_do_step(Instance *c, double t, double h) {
    if (c->phase != PHASE_RUNNING) {
        fmu_log(c, FMU_ERROR, "logStatusError", "do step: the instance is not initialized");
        return FMU_ERROR;
    }
    if (!(h >= 0.0) || !isfinite(h)) {
        fmu_log(c, FMU_ERROR, "logStatusError",
                "do step: the communication step size must be finite and >= 0, got %g", h);
        return FMU_ERROR;
    }
    if (model_step(c, h) > FMU_WARNING) return fail(c);
    for (int i = 0; i < NSTATES; i++) {
        if (!isfinite(c->r[STATE_VR[i]])) {
            fmu_log(c, FMU_ERROR, "logStatusError", "do step: state %s became %g at t = %g",
                    VARIABLES[STATE_VR[i]].name, c->r[STATE_VR[i]], t + h);
            return fail(c);
        }
    }
    c->time = t + h;
    c->outputs_valid = 0;
    /* the outputs at the end of the step are computed here, not at the host's next read: an
     * error of the model there (a chamber without volume) is this step's.  fmi2Error /
     * fmi3Error (FMI 2.0.4 sec. 2.1.3, FMI 3.0 sec. 2.2.3): the instance cannot go on, a host
     * may restore a saved FMU state; not Discard, which asks for a shorter step and would not
     * help here */
    if (update_outputs(c) > FMU_WARNING) return fail(c);
    return FMU_OK;
}

FmuStatus fmu_get_states(Instance *c, double *x, size_t n) {
    if (n != NSTATES) {
        fmu_log(c, FMU_ERROR, "logStatusError", "expected %d states, got %u", NSTATES,
                (unsigned)n);
        return FMU_ERROR;
    }
    for (size_t i = 0; i < n; i++) x[i] = c->r[STATE_VR[i]];
    return FMU_OK;
}

FmuStatus fmu_set_states(Instance *c, const double *x, size_t n) {
    if (n != NSTATES) {
        fmu_log(c, FMU_ERROR, "logStatusError", "expected %d states, got %u", NSTATES,
                (unsigned)n);
        return FMU_ERROR;
    }
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(x[i])) {
            fmu_log(c, FMU_ERROR, "logStatusError", "state %s = %g is not finite",
                    VARIABLES[STATE_VR[i]].name, x[i]);
            return FMU_ERROR;
        }
        c->r[STATE_VR[i]] = x[i];
    }
    c->outputs_valid = 0;
    return FMU_OK;
}

FmuStatus fmu_get_derivatives(Instance *c, double *dx, size_t n) {
    if (n != NSTATES) {
        fmu_log(c, FMU_ERROR, "logStatusError", "expected %d derivatives, got %u", NSTATES,
                (unsigned)n);
        return FMU_ERROR;
    }
    if (n == 0) return FMU_OK;
    if (update_outputs(c) > FMU_WARNING) return fail(c);
    model_derivatives(c, dx);
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(dx[i])) {
            fmu_log(c, FMU_ERROR, "logStatusError", "derivative of %s is not finite",
                    VARIABLES[STATE_VR[i]].name);
            return fail(c);
        }
        if (DERIVATIVE_VR[i] >= 0) c->r[DERIVATIVE_VR[i]] = dx[i];
    }
    return FMU_OK;
}

FmuStatus fmu_get_nominals(Instance *c, double *x, size_t n) {
    if (n != NSTATES) return FMU_ERROR;
    for (size_t i = 0; i < n; i++) x[i] = c->nominals[i];
    return FMU_OK;
}

FmuStatus fmu_get_event_indicators(Instance *c, double *z, size_t n) {
    if (n != NEVENT_INDICATORS) {
        fmu_log(c, FMU_ERROR, "logStatusError", "expected %d event indicators, got %u",
                NEVENT_INDICATORS, (unsigned)n);
        return FMU_ERROR;
    }
#if NEVENT_INDICATORS > 0
    if (update_outputs(c) > FMU_WARNING) return fail(c);
    model_event_indicators(c, z);
#else
    (void)z;
#endif
    return FMU_OK;
}

FmuStatus fmu_new_discrete_states(Instance *c, int *states_changed) {
    *states_changed = 0;
    c->outputs_valid = 0;
#if NEVENT_INDICATORS > 0
    FmuStatus status = model_event_update(c, states_changed);
    if (status > FMU_WARNING) return fail(c);
    return status;
#else
    return update_outputs(c) > FMU_WARNING ? fail(c) : FMU_OK;
#endif
}

double fmu_next_event_time(Instance *c) {
#if MODEL_TIME_EVENTS
    return model_next_event_time(c);
#else
    (void)c;
    return INFINITY;
#endif
}

void fmu_set_time(Instance *c, double t) {
    c->time = t;
    c->outputs_valid = 0;     /* outputs may depend on time (the cylinder's spool) */
}

double fmu_clip(Instance *c, unsigned bit, const char *what, const char *unit, double value,
                double lo, double hi) {
    int outside = value < lo || value > hi;
    if (outside && !(c->clipping & bit)) {
        c->clipping |= bit;
        fmu_log(c, FMU_WARNING, "logStatusWarning",
                "%s = %g %s is outside the table (%g ... %g %s): clipped to the table edge "
                "until it returns", what, value, unit, lo, hi, unit);
    } else if (!outside && (c->clipping & bit)) {
        c->clipping &= ~bit;
        fmu_log(c, FMU_OK, "logEvents", "%s = %g %s is inside the table again", what, value,
                unit);
    }
    return value < lo ? lo : (value > hi ? hi : value);
}
