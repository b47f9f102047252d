"""The rotary steady state as it was before issue 13: one LU factorisation per fixed-point
iteration.  Kept as the reference the faster solver is tested and benchmarked against."""

import math
import warnings

import numpy as np

from sealsim.properties.elastomers import ServiceRangeWarning
from sealsim.properties.oils import OilRangeWarning
from sealsim.rotary.simulation import RotaryModel
from sealsim.thermal.conduction import factorise


def reference_steady_state(case, angular_speed, tol=1e-4, max_iter=100):
    """Fixed-point iteration on the contact and sump temperatures, refactorising each time."""
    model = RotaryModel(case)
    fixed = model.fixed_temperatures()
    t_sump = model.sump_temperature(np.full(model.network.n, model.start_temperature))
    t_contact = t_sump
    temps = np.full(model.network.n, model.start_temperature)
    for iteration in range(1, max_iter + 1):
        k, f = model.assemble(angular_speed, t_sump)
        lu = factorise(k.tocsc())
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", (ServiceRangeWarning, OilRangeWarning))
            state = model.friction.evaluate(angular_speed, t_contact)
        temps = lu.solve(f @ fixed + model.source(float(state.power))
                         + model.bearing_source(model.bearing_heat(angular_speed, temps)))
        new_contact = model.contact_temperature(temps)
        new_sump = model.sump_temperature(temps)
        converged = abs(new_contact - t_contact) < tol and abs(new_sump - t_sump) < tol
        # under-relaxation keeps the iteration monotone when the sump is free: a cold first
        # guess gives a thick oil and a large friction heat that would overshoot the sump
        relax = 0.5 if iteration > 20 or not model.sump_fixed else 1.0
        t_contact = t_contact + relax * (new_contact - t_contact)
        t_sump = t_sump + relax * (new_sump - t_sump)
        if converged:
            break
    else:
        raise RuntimeError(f"reference steady state at {angular_speed * 30 / math.pi:.0f} rpm "
                           f"did not converge")
    return {"torque_Nm": float(state.torque), "power_W": float(state.power),
            "T_contact_C": t_contact - 273.15, "T_sump_C": t_sump - 273.15,
            "T_groove_C": float(temps[model.grid.groove_cell]) - 273.15, "iterations": iteration}
