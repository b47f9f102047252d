"""Exception types for sealsim users.

One type per kind of failure, each with a message that names what to change:

* :class:`InputError` -- a case file, a parameter or a CLI option is invalid.  The message
  names the field, the value given and what is allowed.  The CLI exits with status 2.
* :class:`ResultExistsError` -- an output folder already holds results and ``--force`` was
  not given, or another run is writing to it (:class:`ResultBusyError`) (status 2).
* :class:`OutputError` -- results could not be written (full disk, permissions); the message
  names the file and says that the output folder is unchanged (status 1).
* :class:`ModelError` -- a valid input led to a run that could not be completed (a solver that
  did not converge, a state out of its physical range).  The message says at which step or
  load it failed (status 1).

:class:`SealsimWarning` carries the notes of a result that is valid but worth a look (a contact
above the elastomer's service limit, an illustrative parameter set), issued by the one-call API
(:mod:`sealsim.api`) once per call.

:class:`Terminated` (a :class:`KeyboardInterrupt`) is raised when SIGTERM arrives during a run,
so the clean-up that runs for Ctrl-C runs for SIGTERM too.
"""

from __future__ import annotations


class SealsimError(Exception):
    """Base class of all errors sealsim reports to a user."""

    exit_code = 1


class InputError(SealsimError, ValueError):
    """Invalid user input: the message names the field, the value and what is allowed."""

    exit_code = 2


class ResultExistsError(SealsimError, FileExistsError):
    """An output folder already holds results and overwriting was not requested."""

    exit_code = 2


class ResultBusyError(ResultExistsError):
    """Another run holds the lock of the output folder (two runs to one ``--out``)."""


class OutputError(SealsimError, OSError):
    """Results could not be written (no space left, no permission); names the file."""

    exit_code = 1


class SealsimWarning(UserWarning):
    """A note on a valid result that leaves the range of its models or data (a contact above
    the service limit, a film outside the measured range, an illustrative parameter set)."""


class Terminated(KeyboardInterrupt):
    """SIGTERM during a run: handled like Ctrl-C, so staging folders are removed."""

    exit_code = 143  # 128 + SIGTERM, the shell convention


class ModelError(SealsimError, RuntimeError):
    """A model could not be evaluated for valid input (e.g. no convergence at a load step)."""

    exit_code = 1


class ConvergenceError(ModelError):
    """A nonlinear or time-stepping solver did not converge; the message says where."""
