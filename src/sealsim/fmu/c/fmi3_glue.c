/* FMI 3.0 API (model exchange and co-simulation) on top of the sealsim FMU runtime. */
#include "fmi3Functions.h"
#include "sealsim_fmu.h"

#define INSTANCE ((Instance *)instance)

void glue_log(Instance *c, FmuStatus status, const char *category, const char *message) {
    fmi3LogMessageCallback logger = (fmi3LogMessageCallback)c->logger;
    logger((fmi3InstanceEnvironment)c->environment, (fmi3Status)status, category, message);
}

static fmi3Status unsupported(fmi3Instance instance, const char *function) {
    if (instance != NULL) {
        fmu_log(INSTANCE, FMU_ERROR, "logStatusError", "%s is not supported by this FMU",
                function);
    }
    return fmi3Error;
}

static fmi3Instance instantiate(fmi3String name, fmi3String token, int cosimulation,
                                fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                                fmi3LogMessageCallback logMessage) {
    if (logMessage == NULL) return NULL;
    if (token == NULL || strcmp(token, INSTANTIATION_TOKEN) != 0) {
        logMessage(environment, fmi3Error, "logStatusError",
                   "the instantiation token does not match this FMU's binary: expected "
                   INSTANTIATION_TOKEN);
        return NULL;
    }
    return (fmi3Instance)fmu_instantiate(name, cosimulation, loggingOn ? 1 : 0, environment,
                                         (void (*)(void))logMessage);
}

/* -- common functions ------------------------------------------------------------------------ */
const char *fmi3GetVersion(void) {
    return fmi3Version;
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn,
                               size_t nCategories, const fmi3String categories[]) {
    (void)nCategories;
    (void)categories;
    if (instance == NULL) return fmi3Error;
    INSTANCE->logging_on = loggingOn ? 1 : 0;
    return fmi3OK;
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName,
                                          fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean visible,
                                          fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage) {
    (void)resourcePath;
    (void)visible;
#ifdef MODEL_EXCHANGE
    return instantiate(instanceName, instantiationToken, 0, loggingOn, instanceEnvironment,
                       logMessage);
#else
    (void)instanceName;
    (void)instantiationToken;
    (void)loggingOn;
    if (logMessage != NULL) {
        logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                   "this FMU was built without model exchange");
    }
    return NULL;
#endif
}

fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate) {
    (void)resourcePath;
    (void)visible;
    (void)eventModeUsed;
    (void)earlyReturnAllowed;
    (void)requiredIntermediateVariables;
    (void)nRequiredIntermediateVariables;
    (void)intermediateUpdate;
#ifdef CO_SIMULATION
    return instantiate(instanceName, instantiationToken, 1, loggingOn, instanceEnvironment,
                       logMessage);
#else
    (void)instanceName;
    (void)instantiationToken;
    (void)loggingOn;
    if (logMessage != NULL) {
        logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                   "this FMU was built without co-simulation");
    }
    return NULL;
#endif
}

fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption) {
    (void)instanceName;
    (void)instantiationToken;
    (void)resourcePath;
    (void)visible;
    (void)loggingOn;
    (void)clockUpdate;
    (void)lockPreemption;
    (void)unlockPreemption;
    if (logMessage != NULL) {
        logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                   "scheduled execution is not supported by this FMU");
    }
    return NULL;
}

void fmi3FreeInstance(fmi3Instance instance) {
    if (instance != NULL) fmu_free(INSTANCE);
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined,
                                       fmi3Float64 tolerance, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    if (instance == NULL) return fmi3Error;
    fmu_set_time(INSTANCE, startTime);
    return (fmi3Status)fmu_enter_initialization(INSTANCE);
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    if (instance == NULL) return fmi3Error;
    return (fmi3Status)fmu_exit_initialization(INSTANCE);
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance) {
    return instance == NULL ? fmi3Error : fmi3OK;
}

fmi3Status fmi3Terminate(fmi3Instance instance) {
    if (instance == NULL) return fmi3Error;
    INSTANCE->phase = PHASE_TERMINATED;
    return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance instance) {
    if (instance == NULL) return fmi3Error;
    fmu_reset(INSTANCE);
    return fmi3OK;
}

/* -- getting and setting values -------------------------------------------------------------- */
fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                          size_t nValueReferences, fmi3Float64 values[], size_t nValues) {
    if (instance == NULL) return fmi3Error;
    if (nValues != nValueReferences) return unsupported(instance, "arrays");
    return (fmi3Status)fmu_get_real(INSTANCE, valueReferences, nValueReferences, values);
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                          size_t nValueReferences, const fmi3Float64 values[],
                          size_t nValues) {
    if (instance == NULL) return fmi3Error;
    if (nValues != nValueReferences) return unsupported(instance, "arrays");
    return (fmi3Status)fmu_set_real(INSTANCE, valueReferences, nValueReferences, values);
}

fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                          size_t nValueReferences, fmi3Boolean values[], size_t nValues) {
    if (instance == NULL) return fmi3Error;
    if (nValues != nValueReferences) return unsupported(instance, "arrays");
    for (size_t k = 0; k < nValueReferences; k++) {
        int b = 0;
        FmuStatus status = fmu_get_boolean(INSTANCE, &valueReferences[k], 1, &b);
        if (status > FMU_WARNING) return (fmi3Status)status;
        values[k] = b ? fmi3True : fmi3False;
    }
    return fmi3OK;
}

fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                          size_t nValueReferences, const fmi3Boolean values[],
                          size_t nValues) {
    if (instance == NULL) return fmi3Error;
    if (nValues != nValueReferences) return unsupported(instance, "arrays");
    for (size_t k = 0; k < nValueReferences; k++) {
        int b = values[k] ? 1 : 0;
        FmuStatus status = fmu_set_boolean(INSTANCE, &valueReferences[k], 1, &b);
        if (status > FMU_WARNING) return (fmi3Status)status;
    }
    return fmi3OK;
}

/* the FMU has no variables of the other types */
#define NO_VARIABLES_OF_TYPE(getter, setter, type)                                           \
    fmi3Status getter(fmi3Instance instance, const fmi3ValueReference valueReferences[],    \
                      size_t nValueReferences, type values[], size_t nValues) {             \
        (void)valueReferences;                                                               \
        (void)values;                                                                        \
        (void)nValues;                                                                       \
        return nValueReferences == 0 ? fmi3OK : unsupported(instance, #getter);             \
    }                                                                                        \
    fmi3Status setter(fmi3Instance instance, const fmi3ValueReference valueReferences[],    \
                      size_t nValueReferences, const type values[], size_t nValues) {       \
        (void)valueReferences;                                                               \
        (void)values;                                                                        \
        (void)nValues;                                                                       \
        return nValueReferences == 0 ? fmi3OK : unsupported(instance, #setter);             \
    }

NO_VARIABLES_OF_TYPE(fmi3GetFloat32, fmi3SetFloat32, fmi3Float32)
NO_VARIABLES_OF_TYPE(fmi3GetInt8, fmi3SetInt8, fmi3Int8)
NO_VARIABLES_OF_TYPE(fmi3GetUInt8, fmi3SetUInt8, fmi3UInt8)
NO_VARIABLES_OF_TYPE(fmi3GetInt16, fmi3SetInt16, fmi3Int16)
NO_VARIABLES_OF_TYPE(fmi3GetUInt16, fmi3SetUInt16, fmi3UInt16)
NO_VARIABLES_OF_TYPE(fmi3GetInt32, fmi3SetInt32, fmi3Int32)
NO_VARIABLES_OF_TYPE(fmi3GetUInt32, fmi3SetUInt32, fmi3UInt32)
NO_VARIABLES_OF_TYPE(fmi3GetInt64, fmi3SetInt64, fmi3Int64)
NO_VARIABLES_OF_TYPE(fmi3GetUInt64, fmi3SetUInt64, fmi3UInt64)
NO_VARIABLES_OF_TYPE(fmi3GetString, fmi3SetString, fmi3String)

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                         size_t nValueReferences, size_t valueSizes[], fmi3Binary values[],
                         size_t nValues) {
    (void)valueReferences;
    (void)valueSizes;
    (void)values;
    (void)nValues;
    return nValueReferences == 0 ? fmi3OK : unsupported(instance, "fmi3GetBinary");
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                         size_t nValueReferences, const size_t valueSizes[],
                         const fmi3Binary values[], size_t nValues) {
    (void)valueReferences;
    (void)valueSizes;
    (void)values;
    (void)nValues;
    return nValueReferences == 0 ? fmi3OK : unsupported(instance, "fmi3SetBinary");
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                        size_t nValueReferences, fmi3Clock values[]) {
    (void)valueReferences;
    (void)values;
    return nValueReferences == 0 ? fmi3OK : unsupported(instance, "fmi3GetClock");
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                        size_t nValueReferences, const fmi3Clock values[]) {
    (void)valueReferences;
    (void)values;
    return nValueReferences == 0 ? fmi3OK : unsupported(instance, "fmi3SetClock");
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance,
                                               fmi3ValueReference valueReference,
                                               size_t *nDependencies) {
    (void)valueReference;
    (void)nDependencies;
    return unsupported(instance, "fmi3GetNumberOfVariableDependencies");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference dependent,
                                       size_t elementIndicesOfDependent[],
                                       fmi3ValueReference independents[],
                                       size_t elementIndicesOfIndependents[],
                                       fmi3DependencyKind dependencyKinds[],
                                       size_t nDependencies) {
    (void)dependent;
    (void)elementIndicesOfDependent;
    (void)independents;
    (void)elementIndicesOfIndependents;
    (void)dependencyKinds;
    (void)nDependencies;
    return unsupported(instance, "fmi3GetVariableDependencies");
}

/* -- FMU state: a copy of the instance ------------------------------------------------------------ */
fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *FMUState) {
    if (instance == NULL || FMUState == NULL) return fmi3Error;
    if (*FMUState == NULL) {
        *FMUState = malloc(sizeof(Instance));
        if (*FMUState == NULL) return unsupported(instance, "allocating an FMU state");
    }
    memcpy(*FMUState, instance, sizeof(Instance));
    return fmi3OK;
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState) {
    if (instance == NULL || FMUState == NULL) return fmi3Error;
    Instance keep = *INSTANCE;
    memcpy(instance, FMUState, sizeof(Instance));
    memcpy(INSTANCE->instance_name, keep.instance_name, sizeof keep.instance_name);
    INSTANCE->environment = keep.environment;
    INSTANCE->logger = keep.logger;
    INSTANCE->logging_on = keep.logging_on;
    return fmi3OK;
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *FMUState) {
    (void)instance;
    if (FMUState != NULL && *FMUState != NULL) {
        free(*FMUState);
        *FMUState = NULL;
    }
    return fmi3OK;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState FMUState,
                                      size_t *size) {
    (void)FMUState;
    if (instance == NULL || size == NULL) return fmi3Error;
    *size = sizeof(Instance);
    return fmi3OK;
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState,
                                 fmi3Byte serializedState[], size_t size) {
    if (instance == NULL || FMUState == NULL || size != sizeof(Instance)) return fmi3Error;
    memcpy(serializedState, FMUState, sizeof(Instance));
    return fmi3OK;
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte serializedState[],
                                   size_t size, fmi3FMUState *FMUState) {
    if (instance == NULL || FMUState == NULL || size != sizeof(Instance)) return fmi3Error;
    if (*FMUState == NULL) {
        *FMUState = malloc(sizeof(Instance));
        if (*FMUState == NULL) return fmi3Error;
    }
    memcpy(*FMUState, serializedState, sizeof(Instance));
    return fmi3OK;
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance,
                                        const fmi3ValueReference unknowns[], size_t nUnknowns,
                                        const fmi3ValueReference knowns[], size_t nKnowns,
                                        const fmi3Float64 seed[], size_t nSeed,
                                        fmi3Float64 sensitivity[], size_t nSensitivity) {
    (void)unknowns;
    (void)nUnknowns;
    (void)knowns;
    (void)nKnowns;
    (void)seed;
    (void)nSeed;
    (void)sensitivity;
    (void)nSensitivity;
    return unsupported(instance, "fmi3GetDirectionalDerivative");
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[],
                                    size_t nUnknowns, const fmi3ValueReference knowns[],
                                    size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                    fmi3Float64 sensitivity[], size_t nSensitivity) {
    (void)unknowns;
    (void)nUnknowns;
    (void)knowns;
    (void)nKnowns;
    (void)seed;
    (void)nSeed;
    (void)sensitivity;
    (void)nSensitivity;
    return unsupported(instance, "fmi3GetAdjointDerivative");
}

/* -- configuration, clocks, discrete states (none) -------------------------------------------- */
fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance) {
    return unsupported(instance, "fmi3EnterConfigurationMode");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance) {
    return unsupported(instance, "fmi3ExitConfigurationMode");
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance,
                                  const fmi3ValueReference valueReferences[],
                                  size_t nValueReferences, fmi3Float64 intervals[],
                                  fmi3IntervalQualifier qualifiers[]) {
    (void)valueReferences;
    (void)nValueReferences;
    (void)intervals;
    (void)qualifiers;
    return unsupported(instance, "clocks");
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance instance,
                                   const fmi3ValueReference valueReferences[],
                                   size_t nValueReferences, fmi3UInt64 counters[],
                                   fmi3UInt64 resolutions[],
                                   fmi3IntervalQualifier qualifiers[]) {
    (void)valueReferences;
    (void)nValueReferences;
    (void)counters;
    (void)resolutions;
    (void)qualifiers;
    return unsupported(instance, "clocks");
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                               size_t nValueReferences, fmi3Float64 shifts[]) {
    (void)valueReferences;
    (void)nValueReferences;
    (void)shifts;
    return unsupported(instance, "clocks");
}

fmi3Status fmi3GetShiftFraction(fmi3Instance instance,
                                const fmi3ValueReference valueReferences[],
                                size_t nValueReferences, fmi3UInt64 counters[],
                                fmi3UInt64 resolutions[]) {
    (void)valueReferences;
    (void)nValueReferences;
    (void)counters;
    (void)resolutions;
    return unsupported(instance, "clocks");
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance,
                                  const fmi3ValueReference valueReferences[],
                                  size_t nValueReferences, const fmi3Float64 intervals[]) {
    (void)valueReferences;
    (void)nValueReferences;
    (void)intervals;
    return unsupported(instance, "clocks");
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance instance,
                                   const fmi3ValueReference valueReferences[],
                                   size_t nValueReferences, const fmi3UInt64 counters[],
                                   const fmi3UInt64 resolutions[]) {
    (void)valueReferences;
    (void)nValueReferences;
    (void)counters;
    (void)resolutions;
    return unsupported(instance, "clocks");
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                               size_t nValueReferences, const fmi3Float64 shifts[]) {
    (void)valueReferences;
    (void)nValueReferences;
    (void)shifts;
    return unsupported(instance, "clocks");
}

fmi3Status fmi3SetShiftFraction(fmi3Instance instance,
                                const fmi3ValueReference valueReferences[],
                                size_t nValueReferences, const fmi3UInt64 counters[],
                                const fmi3UInt64 resolutions[]) {
    (void)valueReferences;
    (void)nValueReferences;
    (void)counters;
    (void)resolutions;
    return unsupported(instance, "clocks");
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance) {
    return instance == NULL ? fmi3Error : fmi3OK;
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean *discreteStatesNeedUpdate,
                                    fmi3Boolean *terminateSimulation,
                                    fmi3Boolean *nominalsOfContinuousStatesChanged,
                                    fmi3Boolean *valuesOfContinuousStatesChanged,
                                    fmi3Boolean *nextEventTimeDefined,
                                    fmi3Float64 *nextEventTime) {
    if (instance == NULL) return fmi3Error;
    int changed = 0;
    FmuStatus status = fmu_new_discrete_states(INSTANCE, &changed);
    if (status > FMU_WARNING) return (fmi3Status)status;
    if (discreteStatesNeedUpdate) *discreteStatesNeedUpdate = fmi3False;
    if (terminateSimulation) *terminateSimulation = fmi3False;
    if (nominalsOfContinuousStatesChanged) *nominalsOfContinuousStatesChanged = fmi3False;
    if (valuesOfContinuousStatesChanged)
        *valuesOfContinuousStatesChanged = changed ? fmi3True : fmi3False;
    double next = fmu_next_event_time(INSTANCE);
    if (nextEventTimeDefined) *nextEventTimeDefined = isfinite(next) ? fmi3True : fmi3False;
    if (nextEventTime) *nextEventTime = isfinite(next) ? next : 0.0;
    return fmi3OK;
}

/* -- model exchange -------------------------------------------------------------------------- */
fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance) {
    return instance == NULL ? fmi3Error : fmi3OK;
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance,
                                       fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean *enterEventMode,
                                       fmi3Boolean *terminateSimulation) {
    (void)noSetFMUStatePriorToCurrentPoint;
    if (instance == NULL) return fmi3Error;
    if (enterEventMode) *enterEventMode = fmi3False;
    if (terminateSimulation) *terminateSimulation = fmi3False;
    return fmi3OK;
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time) {
    if (instance == NULL) return fmi3Error;
    fmu_set_time(INSTANCE, time);
    return fmi3OK;
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 continuousStates[],
                                   size_t nContinuousStates) {
    if (instance == NULL) return fmi3Error;
    return (fmi3Status)fmu_set_states(INSTANCE, continuousStates, nContinuousStates);
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 derivatives[],
                                             size_t nContinuousStates) {
    if (instance == NULL) return fmi3Error;
    return (fmi3Status)fmu_get_derivatives(INSTANCE, derivatives, nContinuousStates);
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64 eventIndicators[],
                                  size_t nEventIndicators) {
    if (instance == NULL) return fmi3Error;
    return (fmi3Status)fmu_get_event_indicators(INSTANCE, eventIndicators, nEventIndicators);
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 continuousStates[],
                                   size_t nContinuousStates) {
    if (instance == NULL) return fmi3Error;
    return (fmi3Status)fmu_get_states(INSTANCE, continuousStates, nContinuousStates);
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominals[],
                                             size_t nContinuousStates) {
    if (instance == NULL) return fmi3Error;
    return (fmi3Status)fmu_get_nominals(INSTANCE, nominals, nContinuousStates);
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t *nEventIndicators) {
    if (instance == NULL || nEventIndicators == NULL) return fmi3Error;
    *nEventIndicators = NEVENT_INDICATORS;
    return fmi3OK;
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t *nContinuousStates) {
    if (instance == NULL || nContinuousStates == NULL) return fmi3Error;
    *nContinuousStates = NSTATES;
    return fmi3OK;
}

/* -- co-simulation ----------------------------------------------------------------------------- */
fmi3Status fmi3EnterStepMode(fmi3Instance instance) {
    return instance == NULL ? fmi3Error : fmi3OK;
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance,
                                    const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, const fmi3Int32 orders[],
                                    fmi3Float64 values[], size_t nValues) {
    (void)valueReferences;
    (void)orders;
    (void)values;
    (void)nValues;
    return nValueReferences == 0 ? fmi3OK : unsupported(instance, "fmi3GetOutputDerivatives");
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                      fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime) {
    (void)noSetFMUStatePriorToCurrentPoint;
    if (instance == NULL) return fmi3Error;
    fmi3Status status = (fmi3Status)fmu_do_step(INSTANCE, currentCommunicationPoint,
                                                communicationStepSize);
    if (eventHandlingNeeded) *eventHandlingNeeded = fmi3False;
    if (terminateSimulation) *terminateSimulation = fmi3False;
    if (earlyReturn) *earlyReturn = fmi3False;
    if (lastSuccessfulTime) *lastSuccessfulTime = INSTANCE->time;
    return status;
}

/* -- scheduled execution (not supported) -------------------------------------------------------- */
fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime) {
    (void)clockReference;
    (void)activationTime;
    return unsupported(instance, "scheduled execution");
}
