"""The rotary steady state as it was before issue 13: one LU factorisation per fixed-point
iteration.  Kept as the reference the faster solver is tested and benchmarked against."""

import math
import warnings

import numpy as np

from sealsim.properties.elastomers import ServiceRangeWarning
from sealsim.properties.oils import OilRangeWarning
from sealsim.rotary.simulation import RotaryModel, bearing_heat
from sealsim.thermal.conduction import factorise


def reference_steady_state(case, angular_speed, tol=1e-4, max_iter=100):
    """Fixed-point iteration on the contact, sump and bearing temperatures, refactorising each
    time."""
    model = RotaryModel(case)
    fixed = model.fixed_temperatures()
    start = np.full(model.network.n, model.start_temperature)
    t_sump = model.sump_temperature(start)
    t_contact = t_sump
    t_bearing = model.bearing_temperature(start)
    lowest, highest = model.friction.elastomer.allowed_range
    for iteration in range(1, max_iter + 1):
        k, f = model.assemble(angular_speed, t_sump)
        lu = factorise(k.tocsc())
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", (ServiceRangeWarning, OilRangeWarning))
            # an iterate beyond the rubber's range: its friction at the range's end (as
            # steady_state does on its way)
            state = model.friction.evaluate(angular_speed, min(max(t_contact, lowest), highest))
        bearing = bearing_heat(case, model.oil, angular_speed, t_bearing)
        temps = lu.solve(f @ fixed + model.source(float(state.power))
                         + model.bearing_source(bearing))
        new_contact = model.contact_temperature(temps)
        new_sump = model.sump_temperature(temps)
        new_bearing = model.bearing_temperature(temps)
        converged = max(abs(new_contact - t_contact), abs(new_sump - t_sump),
                        abs(new_bearing - t_bearing)) < tol
        # under-relaxation keeps the iteration monotone when the sump is free: a cold first
        # guess gives a thick oil and a large friction heat that would overshoot the sump
        relax = 0.5 if iteration > 20 or not model.sump_fixed else 1.0
        t_contact = t_contact + relax * (new_contact - t_contact)
        t_sump = t_sump + relax * (new_sump - t_sump)
        t_bearing = t_bearing + relax * (new_bearing - t_bearing)
        if converged:
            break
    else:
        raise RuntimeError(f"reference steady state at {angular_speed * 30 / math.pi:.0f} rpm "
                           f"did not converge")
    return {"torque_Nm": float(state.torque), "power_W": float(state.power),
            "T_contact_C": t_contact - 273.15, "T_sump_C": t_sump - 273.15,
            "T_groove_C": float(temps[model.grid.groove_cell]) - 273.15, "iterations": iteration}
