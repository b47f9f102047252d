/* FMI 2.0 API (model exchange and co-simulation) on top of the sealsim FMU runtime. */
#include "fmi2Functions.h"
#include "sealsim_fmu.h"

#define INSTANCE ((Instance *)c)

void glue_log(Instance *c, FmuStatus status, const char *category, const char *message) {
    fmi2CallbackLogger logger = (fmi2CallbackLogger)c->logger;
    logger((fmi2ComponentEnvironment)c->environment, c->instance_name, (fmi2Status)status,
           category, message);
}

static fmi2Status unsupported(fmi2Component c, const char *function) {
    if (c != NULL) {
        fmu_log(INSTANCE, FMU_ERROR, "logStatusError", "%s is not supported by this FMU",
                function);
    }
    return fmi2Error;
}

/* -- common functions ------------------------------------------------------------------------ */
const char *fmi2GetTypesPlatform(void) {
    return fmi2TypesPlatform;
}

const char *fmi2GetVersion(void) {
    return fmi2Version;
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    (void)nCategories;
    (void)categories;
    if (c == NULL) return fmi2Error;
    INSTANCE->logging_on = loggingOn ? 1 : 0;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn) {
    (void)fmuResourceLocation;
    (void)visible;
    if (functions == NULL || functions->logger == NULL) return NULL;
    if (fmuGUID == NULL || strcmp(fmuGUID, INSTANTIATION_TOKEN) != 0) {
        functions->logger(functions->componentEnvironment, instanceName, fmi2Error,
                          "logStatusError",
                          "the GUID does not match this FMU's binary: expected "
                          INSTANTIATION_TOKEN);
        return NULL;
    }
#ifndef MODEL_EXCHANGE
    if (fmuType == fmi2ModelExchange) {
        functions->logger(functions->componentEnvironment, instanceName, fmi2Error,
                          "logStatusError", "this FMU was built without model exchange");
        return NULL;
    }
#endif
#ifndef CO_SIMULATION
    if (fmuType == fmi2CoSimulation) {
        functions->logger(functions->componentEnvironment, instanceName, fmi2Error,
                          "logStatusError", "this FMU was built without co-simulation");
        return NULL;
    }
#endif
    return (fmi2Component)fmu_instantiate(instanceName, fmuType == fmi2CoSimulation,
                                          loggingOn ? 1 : 0, functions->componentEnvironment,
                                          (void (*)(void))functions->logger);
}

void fmi2FreeInstance(fmi2Component c) {
    if (c != NULL) fmu_free(INSTANCE);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                               fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    if (c == NULL) return fmi2Error;
    fmu_set_time(INSTANCE, startTime);
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    if (c == NULL) return fmi2Error;
    return (fmi2Status)fmu_enter_initialization(INSTANCE);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    if (c == NULL) return fmi2Error;
    return (fmi2Status)fmu_exit_initialization(INSTANCE);
}

fmi2Status fmi2Terminate(fmi2Component c) {
    if (c == NULL) return fmi2Error;
    INSTANCE->phase = PHASE_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
    if (c == NULL) return fmi2Error;
    fmu_reset(INSTANCE);
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
    if (c == NULL) return fmi2Error;
    return (fmi2Status)fmu_get_real(INSTANCE, vr, nvr, value);
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[]) {
    (void)vr;
    (void)value;
    return nvr == 0 ? fmi2OK : unsupported(c, "fmi2GetInteger");
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[]) {
    if (c == NULL) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        int b = 0;
        FmuStatus status = fmu_get_boolean(INSTANCE, &vr[k], 1, &b);
        if (status > FMU_WARNING) return (fmi2Status)status;
        value[k] = b ? fmi2True : fmi2False;
    }
    return fmi2OK;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[]) {
    (void)vr;
    (void)value;
    return nvr == 0 ? fmi2OK : unsupported(c, "fmi2GetString");
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
    if (c == NULL) return fmi2Error;
    return (fmi2Status)fmu_set_real(INSTANCE, vr, nvr, value);
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[]) {
    (void)vr;
    (void)value;
    return nvr == 0 ? fmi2OK : unsupported(c, "fmi2SetInteger");
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[]) {
    if (c == NULL) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        int b = value[k] ? 1 : 0;
        FmuStatus status = fmu_set_boolean(INSTANCE, &vr[k], 1, &b);
        if (status > FMU_WARNING) return (fmi2Status)status;
    }
    return fmi2OK;
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[]) {
    (void)vr;
    (void)value;
    return nvr == 0 ? fmi2OK : unsupported(c, "fmi2SetString");
}

/* -- FMU state: a copy of the instance ------------------------------------------------------------ */
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *state) {
    if (c == NULL || state == NULL) return fmi2Error;
    if (*state == NULL) {
        *state = malloc(sizeof(Instance));
        if (*state == NULL) return unsupported(c, "allocating an FMU state");
    }
    memcpy(*state, c, sizeof(Instance));
    return fmi2OK;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) {
    if (c == NULL || state == NULL) return fmi2Error;
    Instance *saved = (Instance *)state;
    /* keep this instance's identity (name, logger) and take the saved model state */
    Instance keep = *INSTANCE;
    memcpy(c, saved, sizeof(Instance));
    memcpy(INSTANCE->instance_name, keep.instance_name, sizeof keep.instance_name);
    INSTANCE->environment = keep.environment;
    INSTANCE->logger = keep.logger;
    INSTANCE->logging_on = keep.logging_on;
    return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *state) {
    (void)c;
    if (state != NULL && *state != NULL) {
        free(*state);
        *state = NULL;
    }
    return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t *size) {
    (void)state;
    if (c == NULL || size == NULL) return fmi2Error;
    *size = sizeof(Instance);
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[],
                                 size_t size) {
    if (c == NULL || state == NULL || size != sizeof(Instance)) return fmi2Error;
    memcpy(bytes, state, sizeof(Instance));
    return fmi2OK;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size,
                                   fmi2FMUstate *state) {
    if (c == NULL || state == NULL || size != sizeof(Instance)) return fmi2Error;
    if (*state == NULL) {
        *state = malloc(sizeof(Instance));
        if (*state == NULL) return fmi2Error;
    }
    memcpy(*state, bytes, sizeof(Instance));
    return fmi2OK;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c,
                                        const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[]) {
    (void)vUnknown_ref;
    (void)nUnknown;
    (void)vKnown_ref;
    (void)nKnown;
    (void)dvKnown;
    (void)dvUnknown;
    return unsupported(c, "fmi2GetDirectionalDerivative");
}

/* -- model exchange -------------------------------------------------------------------------- */
fmi2Status fmi2EnterEventMode(fmi2Component c) {
    return c == NULL ? fmi2Error : fmi2OK;
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *info) {
    if (c == NULL || info == NULL) return fmi2Error;
    int changed = 0;
    FmuStatus status = fmu_new_discrete_states(INSTANCE, &changed);
    if (status > FMU_WARNING) return (fmi2Status)status;
    info->newDiscreteStatesNeeded = fmi2False;
    info->terminateSimulation = fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False;
    info->valuesOfContinuousStatesChanged = changed ? fmi2True : fmi2False;
    double next = fmu_next_event_time(INSTANCE);
    info->nextEventTimeDefined = isfinite(next) ? fmi2True : fmi2False;
    info->nextEventTime = isfinite(next) ? next : 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
    return c == NULL ? fmi2Error : fmi2OK;
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component c,
                                       fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi2Boolean *enterEventMode,
                                       fmi2Boolean *terminateSimulation) {
    (void)noSetFMUStatePriorToCurrentPoint;
    if (c == NULL || enterEventMode == NULL || terminateSimulation == NULL) return fmi2Error;
    *enterEventMode = fmi2False;
    *terminateSimulation = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time) {
    if (c == NULL) return fmi2Error;
    fmu_set_time(INSTANCE, time);
    return fmi2OK;
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx) {
    if (c == NULL) return fmi2Error;
    return (fmi2Status)fmu_set_states(INSTANCE, x, nx);
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[], size_t nx) {
    if (c == NULL) return fmi2Error;
    return (fmi2Status)fmu_get_derivatives(INSTANCE, derivatives, nx);
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[], size_t ni) {
    if (c == NULL) return fmi2Error;
    return (fmi2Status)fmu_get_event_indicators(INSTANCE, eventIndicators, ni);
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {
    if (c == NULL) return fmi2Error;
    return (fmi2Status)fmu_get_states(INSTANCE, x, nx);
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[],
                                             size_t nx) {
    if (c == NULL) return fmi2Error;
    return (fmi2Status)fmu_get_nominals(INSTANCE, x_nominal, nx);
}

/* -- co-simulation ----------------------------------------------------------------------------- */
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                       size_t nvr, const fmi2Integer order[],
                                       const fmi2Real value[]) {
    (void)vr;
    (void)order;
    (void)value;
    return nvr == 0 ? fmi2OK : unsupported(c, "fmi2SetRealInputDerivatives");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Integer order[],
                                        fmi2Real value[]) {
    (void)vr;
    (void)order;
    (void)value;
    return nvr == 0 ? fmi2OK : unsupported(c, "fmi2GetRealOutputDerivatives");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint;
    if (c == NULL) return fmi2Error;
    return (fmi2Status)fmu_do_step(INSTANCE, currentCommunicationPoint, communicationStepSize);
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    return unsupported(c, "fmi2CancelStep");
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetStatus");
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    if (c == NULL || value == NULL) return fmi2Error;
    if (s == fmi2LastSuccessfulTime) {
        *value = INSTANCE->time;
        return fmi2OK;
    }
    return unsupported(c, "fmi2GetRealStatus for this status kind");
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetIntegerStatus");
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetBooleanStatus");
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetStringStatus");
}
