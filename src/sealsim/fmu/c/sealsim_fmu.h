/* sealsim FMU runtime: what the FMI glue (fmi2_glue.c, fmi3_glue.c) and a model
 * (friction_model.c, rotary_model.c) share.
 *
 * Every variable of an FMU is a double in Instance.r[], indexed by its value reference
 * (Booleans are stored as 0/1).  The generated config.h defines the value references
 * (VR_... macros), the variable table VARIABLES[] with the bounds of every parameter,
 * START_VALUES[], the continuous states (STATE_VR[], DERIVATIVE_VR[]) and the model's
 * tables.  Part of the FMUs that sealsim.fmu generates: plain C99, no dependencies beyond
 * the C library and the FMI headers.
 */
#ifndef SEALSIM_FMU_H
#define SEALSIM_FMU_H

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef enum {
    FMU_OK = 0,
    FMU_WARNING = 1,
    FMU_DISCARD = 2,
    FMU_ERROR = 3,
    FMU_FATAL = 4
} FmuStatus;

/* causality of a variable */
enum { CAUSALITY_PARAMETER, CAUSALITY_INPUT, CAUSALITY_OUTPUT, CAUSALITY_LOCAL,
       CAUSALITY_INDEPENDENT };

/* life-cycle phase of an instance */
enum { PHASE_INSTANTIATED, PHASE_INITIALIZATION, PHASE_RUNNING, PHASE_TERMINATED,
       PHASE_ERROR };

/* when a variable may be set: never (computed), before the end of initialization
 * (parameters, start values of states) or at any time (inputs) */
enum { SET_NEVER, SET_BEFORE_INIT, SET_ALWAYS };

/* a lower/upper bound: BOUND_NONE, inclusive (>=, <=) or exclusive (>, <) */
enum { BOUND_NONE, BOUND_INCLUSIVE, BOUND_EXCLUSIVE };

typedef struct {
    const char *name;
    const char *unit;      /* for messages */
    int causality;
    int is_boolean;
    int settable;          /* SET_NEVER, SET_BEFORE_INIT or SET_ALWAYS */
    int lower_kind;
    double lower;
    int upper_kind;
    double upper;
} VariableInfo;

/* fmin and fmax inlined, with the C library's results (glibc: a NaN operand gives the other
 * one, equal operands -- +0 and -0 too -- the first): a compiler inlines the library's only
 * with -ffinite-math-only -fno-signed-zeros, so each was a call into libm, 76 per right-hand
 * side of the cylinder */
static inline double fmin_inline(double a, double b) { return (b < a || a != a) ? b : a; }
static inline double fmax_inline(double a, double b) { return (b > a || a != a) ? b : a; }

/* a C1 piecewise-cubic Hermite table on a rectilinear 2-D grid (hermite.c) */
typedef struct {
    int n0, n1, nvars;
    const double *x0, *x1;
    /* per node (i0, i1): nvars values, nvars d/dx0, nvars d/dx1, nvars d2/dx0dx1 */
    const double *data;
} HermiteTable;

void hermite_evaluate(const HermiteTable *t, double a, double b, double *out);

/* a seal's steady friction table from its contact (contact_table.c): the interpolant of
 * sealsim.friction.contact_table (asperity load [N/m], viscous friction [N/m], film [m] of the
 * stroke direction of speed), the Theta law's steady curve |F_ss(v)| (the asperity load at
 * the speed film [m/s] the contact's film has formed for) with its boundary part
 * pi D mu_b L [N] (the base of the dwell drop), its friction level, and the film's speed:
 * dphi/dt = (|v| - phi)(|v|/b + 1/tau), its exact step phi(t + dt) = a phi + c for v, b
 * held */
void contact_table_point(const long *row, const double *data, double temperature,
                         double pressure, double speed, double *load, double *visc,
                         double *film);
void contact_steady(const long *row, const double *data, double temperature, double pressure,
                    double oriented_speed, double film, double circumference,
                    double boundary_friction, double *steady, double *boundary,
                    double *viscous, double *decay);
double film_decay_rate(const long *row, const double *data, double temperature,
                       double pressure, double film);
double theta_contact_level(double th, double v, double fss, double fb, double d,
                           double thss, double fv);
double film_speed_rate(double phi, double v, double b, double decay);
void film_speed_affine(double v, double dt, double b, double decay, double *a, double *c);

#include "config.h"

#if NSTATES > 0
#define STATE_ARRAY_SIZE NSTATES
#else
#define STATE_ARRAY_SIZE 1
#endif
#ifndef NEVENT_INDICATORS
#define NEVENT_INDICATORS 0
#endif
/* memory of the model beyond the variables (the cylinder's mode and integrator state), as
 * doubles so that it is aligned for any member; copied with the FMU state */
#ifndef MODEL_WORK_DOUBLES
#define MODEL_WORK_DOUBLES 1
#endif
#ifndef MODEL_TIME_EVENTS
#define MODEL_TIME_EVENTS 0
#endif

typedef struct {
    double r[NVARS];          /* every variable by value reference */
    double time;
    int phase;
    int cosimulation;         /* 1: co-simulation, 0: model exchange */
    int logging_on;
    int outputs_valid;        /* outputs are up to date with inputs, parameters and states */
    unsigned clipping;        /* bit set of quantities clipped to their table (warned once) */
    int cache_valid;          /* cache holds what the model derived from inputs and parameters */
    double cache[8];
    double nominals[STATE_ARRAY_SIZE];
    char instance_name[128];
    void *environment;        /* the host's environment pointer, handed back to the logger */
    void (*logger)(void);     /* the host's logger; cast by the glue of its FMI version */
    double work[MODEL_WORK_DOUBLES];
} Instance;

/* -- provided by the glue of the FMI version -------------------------------------------- */
void glue_log(Instance *c, FmuStatus status, const char *category, const char *message);

/* -- provided by the model ------------------------------------------------------------------ */
/* Checks between parameters (bounds of single parameters are checked by the runtime). */
FmuStatus model_check_parameters(Instance *c);
/* Initial states and state nominals at the end of initialization. */
FmuStatus model_initialize(Instance *c);
/* Outputs from the states, inputs and parameters. */
FmuStatus model_outputs(Instance *c);
/* dx/dt of the continuous states (model exchange). */
void model_derivatives(Instance *c, double *dx);
/* Advance the states by h with the inputs held constant (co-simulation): exact or implicit. */
FmuStatus model_step(Instance *c, double h);
#if MODEL_TIME_EVENTS
/* The next time event (model exchange), INFINITY for none. */
double model_next_event_time(Instance *c);
#endif
#if NEVENT_INDICATORS > 0
/* The event indicators (model exchange); a discrete state switches where one crosses 0. */
void model_event_indicators(Instance *c, double *z);
/* Event mode: switch the discrete states; *states_changed when continuous states were set. */
FmuStatus model_event_update(Instance *c, int *states_changed);
#endif

/* -- the runtime (fmu_runtime.c) ---------------------------------------------------------- */
void fmu_log(Instance *c, FmuStatus status, const char *category, const char *format, ...);
Instance *fmu_instantiate(const char *name, int cosimulation, int logging_on,
                          void *environment, void (*logger)(void));
void fmu_free(Instance *c);
void fmu_reset(Instance *c);
FmuStatus fmu_get_real(Instance *c, const unsigned *vr, size_t n, double *value);
FmuStatus fmu_set_real(Instance *c, const unsigned *vr, size_t n, const double *value);
FmuStatus fmu_get_boolean(Instance *c, const unsigned *vr, size_t n, int *value);
FmuStatus fmu_set_boolean(Instance *c, const unsigned *vr, size_t n, const int *value);
FmuStatus fmu_enter_initialization(Instance *c);
FmuStatus fmu_exit_initialization(Instance *c);
FmuStatus fmu_do_step(Instance *c, double t, double h);
FmuStatus fmu_get_states(Instance *c, double *x, size_t n);
FmuStatus fmu_set_states(Instance *c, const double *x, size_t n);
FmuStatus fmu_get_derivatives(Instance *c, double *dx, size_t n);
FmuStatus fmu_get_nominals(Instance *c, double *x, size_t n);
FmuStatus fmu_get_event_indicators(Instance *c, double *z, size_t n);
FmuStatus fmu_new_discrete_states(Instance *c, int *states_changed);
/* the next time event of the model (model exchange); INFINITY for none */
double fmu_next_event_time(Instance *c);
void fmu_set_time(Instance *c, double t);
/* Clip value to [lo, hi]; warn once when it leaves the range (bit: a CLIP_... flag). */
double fmu_clip(Instance *c, unsigned bit, const char *what, const char *unit, double value,
                double lo, double hi);

#endif
