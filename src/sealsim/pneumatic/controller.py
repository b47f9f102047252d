"""The controller: a PLC cycle of valve commands, or a prescribed piston position (test rig).

**PLC cycle** (Heipl & Murrenhoff Fig. 5: the PLC "triggers the valve with a typical driving
cycle"): a list of steps, each a valve command held for a duration -- e.g. extend 1 s, retract 1 s,
a rectangular signal; a dwell is a step with the valve in its centre position (5/3) or simply a
longer step.  The cycle repeats until the end of the simulated time.

**Prescribed position** (friction test rigs, Heipl & Murrenhoff Fig. 11: the tube is driven by a
crank, the pressurised test seal sits on a fixed piston): the piston position x(t) is given (a
harmonic crank motion or a piecewise-linear profile), the chambers still follow the valve,
and the friction of each seal is what the rig's force sensor reads.

Commands: ``"extend"`` (spool +1: port A = cap side to supply, B to exhaust), ``"retract"``
(−1) and, for 5/3 valves, ``"centre"`` (0).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sealsim.errors import InputError

__all__ = ["COMMANDS", "CommandSchedule", "command_schedule"]

#: spool target of each command
COMMANDS = {"extend": 1.0, "retract": -1.0, "centre": 0.0}


@dataclass(frozen=True)
class CommandSchedule:
    """Valve commands issued at given times (piecewise constant).

    Parameters
    ----------
    times : ndarray
        Issue times t_k [s], strictly ascending, the first >= 0.
    commands : ndarray
        Spool targets u_k (+1, −1, 0) issued at t_k.
    initial : float
        Command in force before the first issue time (the valve's rest position).

    Examples
    --------
    >>> s = CommandSchedule.from_cycle([("extend", 1.0), ("retract", 1.0)], duration=3.5)
    >>> s.times, s.commands
    (array([0., 1., 2., 3.]), array([ 1., -1.,  1., -1.]))
    >>> s.command_at([0.5, 1.0, 3.4])
    array([ 1., -1., -1.])
    """

    times: np.ndarray
    commands: np.ndarray
    initial: float = -1.0

    @classmethod
    def from_cycle(cls, steps, duration: float, initial: str | float = "retract",
                   start: float = 0.0) -> CommandSchedule:
        """Repeat a cycle of ``(command, duration)`` steps from ``start`` until ``duration``.

        Consecutive equal commands are merged (one issue time).
        """
        if not steps:
            raise InputError("controller.steps: give at least one step, e.g. "
                             "[{command = 'extend', duration = '1 s'}]")
        period = sum(float(d) for _, d in steps)
        if period <= 0:
            raise InputError("controller.steps: the durations must add up to more than 0 s")
        u0 = COMMANDS[initial] if isinstance(initial, str) else float(initial)
        times, commands = [], []
        t = float(start)
        last = u0
        while t < duration:
            for command, length in steps:
                if t >= duration:
                    break
                u = COMMANDS[command] if isinstance(command, str) else float(command)
                if not times or u != last:
                    times.append(t)
                    commands.append(u)
                    last = u
                t += float(length)
        return cls(np.asarray(times, dtype=float), np.asarray(commands, dtype=float), u0)

    def command_at(self, t):
        """Command in force at time(s) t [s]."""
        t = np.asarray(t, dtype=float)
        k = np.searchsorted(self.times, t, side="right") - 1
        values = self.commands[np.clip(k, 0, max(len(self.commands) - 1, 0))] \
            if len(self.commands) else np.full(t.shape, self.initial)
        return np.where(k < 0, self.initial, values)

    def windows(self, target: float):
        """(start, end) times [s] of every issue of the command ``target`` (+1/−1/0); the
        end is the next issue time or ``inf``."""
        out = []
        for k, u in enumerate(self.commands):
            if u == target:
                end = self.times[k + 1] if k + 1 < len(self.times) else np.inf
                out.append((float(self.times[k]), float(end)))
        return out


def command_schedule(case) -> CommandSchedule:
    """The valve commands of a pneumatic case: its PLC cycle, or (position mode) the command
    held from t = 0."""
    ctrl = case.controller
    if ctrl.mode == "cycle":
        return CommandSchedule.from_cycle([(s.command, s.duration) for s in ctrl.steps],
                                          ctrl.duration, initial=ctrl.initial_command)
    u = COMMANDS[ctrl.command]
    return CommandSchedule(np.array([0.0]), np.array([u]), u)
