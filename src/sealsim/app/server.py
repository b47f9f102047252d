"""The Flask application behind ``sealsim app``: one page, four calculators, JSON endpoints.

Every number comes from the public API (:mod:`sealsim.api`) called with unit strings as the
page sends them ("80 mm", "1500 rpm"); the page shows the API's notes (warnings of sealsim's
own classes and any ``notes`` the API returns).  Long work runs in child processes
(:mod:`sealsim.app.jobs`).
"""

from __future__ import annotations

import base64
import io
import math
import tomllib
import warnings
import zipfile
from pathlib import Path
from typing import Any

import numpy as np
from flask import Flask, jsonify, request, send_file

from sealsim.app.jobs import JobManager
from sealsim.errors import InputError, SealsimError

__all__ = ["AppConfig", "create_app"]

STATIC = Path(__file__).resolve().parent / "static"
EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "gland"

#: Longest text of one form field [characters].
MAX_FIELD = 200
#: duty.steady_rate of the rotary case the lip-seal page offers: a run ends within about
#: 0.2 K of the page's steady state (a free sump's remaining rise is the rate times its time
#: constant of about an hour)
APP_STEADY_RATE = "0.005 K/min"


class AppConfig:
    """Limits of the app: upload size [bytes], run time [s], runs at once, work folder."""

    def __init__(self, work_dir: Path, max_upload: int = 512 * 1024, run_timeout: float = 600.0,
                 max_running: int = 2):
        self.work_dir = Path(work_dir)
        self.max_upload = int(max_upload)
        self.run_timeout = float(run_timeout)
        self.max_running = int(max_running)


def create_app(config: AppConfig) -> Flask:
    """The Flask app (its :class:`~sealsim.app.jobs.JobManager` is ``app.extensions
    ["sealsim_jobs"]``)."""
    app = Flask("sealsim.app", static_folder=str(STATIC), static_url_path="/static")
    app.config["MAX_CONTENT_LENGTH"] = config.max_upload
    jobs = JobManager(config.work_dir, config.run_timeout, config.max_running)
    app.extensions["sealsim_jobs"] = jobs

    @app.errorhandler(SealsimError)
    def _sealsim_error(exc):
        from sealsim.cli._common import error_parts

        kind, message = error_parts(exc)
        return jsonify({"error": f"{kind}: {message}"}), 400

    @app.errorhandler(413)
    def _too_large(exc):
        return jsonify({"error": f"input error: the upload is larger than the app's limit of "
                                 f"{config.max_upload // 1024} kB"}), 413

    @app.errorhandler(404)
    def _not_found(exc):
        return jsonify({"error": "not found"}), 404

    @app.get("/")
    def index():
        return send_file(STATIC / "index.html")

    @app.get("/api/options")
    def options():
        from sealsim.friction import PARAMETER_SETS
        from sealsim.properties import list_elastomers, list_oils

        return jsonify({"oils": list_oils(), "materials": list_elastomers(),
                        "laws": {k: sorted(v) for k, v in PARAMETER_SETS.items()},
                        "gland_examples": gland_examples(),
                        "limits": {"upload_kB": config.max_upload // 1024,
                                   "run_timeout_s": config.run_timeout}})

    @app.post("/api/lip-seal")
    def lip_seal():
        import sealsim

        form = _form(request.get_json(silent=True))
        args = _lip_arguments(form)
        result, notes = call_with_notes(sealsim.lip_seal_torque, **args)
        return _json({"point": result, "notes": notes, "case_toml": rotary_case_toml(args)})

    @app.post("/api/lip-seal/curve")
    def lip_seal_curve():
        import sealsim
        from sealsim.plotting.calculators import figure_png, lip_seal_speed_figure

        form = _form(request.get_json(silent=True))
        args = _lip_arguments(form)
        low, high = (_number(form, k, "rpm") for k in ("speed_min", "speed_max"))
        if not 0 <= low < high <= 20000:
            raise InputError(f"speed range: {low:g} ... {high:g} rpm; give 0 <= lowest < "
                             "highest <= 20000 rpm")
        speeds = [f"{n:.6g} rpm" for n in np.linspace(low, high, 12)]
        point = args.pop("speed")
        curve, notes = call_with_notes(sealsim.lip_seal_torque, speed=speeds, **args)
        marked, _ = call_with_notes(sealsim.lip_seal_torque, speed=point, **args)
        figure = lip_seal_speed_figure(curve, marked, f"{form['shaft_diameter']} shaft, "
                                                      f"{form['oil']}, {form['material']}")
        return _json({"curve": curve.to_dict(orient="records"), "notes": notes,
                      "figure": _png_data(figure_png(figure))})

    @app.get("/api/gland/example/<name>")
    def gland_example(name):
        if name not in gland_examples():
            return jsonify({"error": f"no gland example {name!r}"}), 404
        return jsonify({"name": name, "toml": (EXAMPLES / f"{name}.toml").read_text("utf-8")})

    @app.post("/api/gland")
    def gland():
        import sealsim

        from sealsim.plotting.gland import check_label

        report, notes = call_with_notes(sealsim.oring_gland, _gland_case(request))
        for check in report["checks"]:        # named as the CLI prints them
            check["label"] = check_label(check)
        return _json({"report": report, "notes": _merge(report.get("notes", []), notes)})

    @app.post("/api/gland/figure")
    def gland_figure():
        import sealsim
        from sealsim.plotting.calculators import figure_png
        from sealsim.plotting.gland import plot_gland_section

        case = _gland_case(request)
        report, _ = call_with_notes(sealsim.oring_gland, case)
        return _json({"figure": _png_data(figure_png(plot_gland_section(case, report)))})

    @app.post("/api/gland/fe")
    def gland_fe():
        from sealsim.cases import validate_case
        from sealsim.structure.gland_case import GlandCase

        gland_data = _gland_tables(request.get_json(silent=True))
        case = validate_case(GlandCase, gland_data, "gland")   # refuse a bad gland at once
        if case.fe is None:
            raise InputError("fe: the FE check needs the case's [fe] table with the sliding "
                             "velocity, e.g. [fe] velocity = '0.1 m/s'")
        job = jobs.start("gland_fe", {"gland": gland_data})
        return jsonify({"token": job.token})

    @app.post("/api/friction")
    def friction():
        import sealsim
        from sealsim.plotting.calculators import figure_png, friction_figure

        form = _form(request.get_json(silent=True))
        _require(form, "cord_diameter", "squeeze", "law", "parameter_set", "pressure",
                 "temperature", "diameter", "amplitude", "frequency", "mean_velocity")
        seal = {"cord_diameter": form["cord_diameter"],
                "squeeze": _number(form, "squeeze", "%") / 100.0,
                "elastomer": form.get("elastomer", "NBR")}
        law = {"law": form["law"], "parameter_set": form["parameter_set"]}
        common = {"pressure": form["pressure"], "temperature": form["temperature"],
                  "law": law, "diameter": form["diameter"]}
        low, high = (_number(form, k, "m/s") for k in ("velocity_min", "velocity_max"))
        if not 0 < low < high <= 20:
            raise InputError(f"velocity range: {low:g} ... {high:g} m/s; give 0 < lowest < "
                             "highest <= 20 m/s")
        velocities = [f"{v:.6g} m/s" for v in np.geomspace(low, high, 40)]
        curve, notes = call_with_notes(sealsim.seal_friction, seal, velocities, **common)
        loop, loop_notes = call_with_notes(
            sealsim.friction_loop, seal, form["amplitude"], form["frequency"],
            mean_velocity=form["mean_velocity"], cycles=3, **common)
        title = (f"O-ring {form['cord_diameter']}, {form['squeeze']} squeeze on "
                 f"{form['diameter']}, {form['pressure']}, {form['temperature']}; "
                 f"{law['law']} ({law['parameter_set']})")
        last = loop.iloc[-(len(loop) // 3 + 1):]
        return _json({"curve": curve.to_dict(orient="records"),
                      "loop_last_cycle": {"friction_min_N": float(last["friction_N"].min()),
                                          "friction_max_N": float(last["friction_N"].max())},
                      "normal_force_N": float(curve["normal_force_N"].iloc[0]),
                      "contact_width_mm": float(curve["contact_width_mm"].iloc[0]),
                      "notes": _merge(notes, loop_notes),
                      "figure": _png_data(figure_png(friction_figure(curve, loop, title)))})

    @app.post("/api/run")
    def run():
        upload = request.files.get("case")
        if upload is None:
            raise InputError("no case file: choose a case TOML to upload")
        raw = upload.read(config.max_upload + 1)
        if len(raw) > config.max_upload:
            raise InputError(f"the upload is larger than the app's limit of "
                             f"{config.max_upload // 1024} kB")
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError:
            raise InputError("case file 'case.toml' is not UTF-8 text") from None
        job = jobs.start("case", {}, case_text=text)
        return jsonify({"token": job.token})

    @app.get("/api/jobs/<token>")
    def job_status(token):
        job = _job(token)
        out = job.public()
        out["files"] = jobs.files(job)
        return _json(out)

    @app.get("/api/jobs/<token>/file/<path:name>")
    def job_file(token, name):
        path = jobs.result_path(_job(token), name)
        if path is None:
            return jsonify({"error": f"no result file {name!r}"}), 404
        return send_file(path, max_age=0)

    @app.get("/api/jobs/<token>/result.zip")
    def job_zip(token):
        job = _job(token)
        buffer = io.BytesIO()
        with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
            for name in jobs.files(job):
                archive.write(jobs.result_path(job, name), f"result/{name}")
        buffer.seek(0)
        return send_file(buffer, mimetype="application/zip", as_attachment=True,
                         download_name=f"sealsim-{job.kind}-result.zip")

    def _job(token):
        job = jobs.get(token)
        if job is None:
            from werkzeug.exceptions import NotFound

            raise NotFound()
        return job

    return app


def gland_examples() -> list[str]:
    """Names of the gland examples the page offers (examples/gland/*.toml)."""
    return sorted(p.stem for p in EXAMPLES.glob("*.toml")) if EXAMPLES.is_dir() else []


def call_with_notes(function, *args, **kwargs):
    """``function(*args, **kwargs)`` and the notes it gave: warnings of sealsim's own
    classes (once each) and a ``notes`` entry of the result (a dict key or DataFrame
    attribute), whichever the API uses."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = function(*args, **kwargs)
    notes = [str(w.message) for w in caught
             if getattr(w.category, "__module__", "").startswith("sealsim")]
    extra = result.get("notes") if isinstance(result, dict) else \
        getattr(result, "attrs", {}).get("notes")
    return result, _merge(notes, extra or [])


def _merge(*lists) -> list[str]:
    return list(dict.fromkeys(str(n) for items in lists for n in items))


def _form(data) -> dict[str, str]:
    """The page's form as strings (numbers with their units); anything else is refused."""
    if not isinstance(data, dict):
        raise InputError("the request holds no form data")
    out = {}
    for key, value in data.items():
        if value is None:
            continue
        if not isinstance(value, str) or len(value) > MAX_FIELD:
            raise InputError(f"{key}: {str(value)[:40]!r} is not a short text "
                             f"(at most {MAX_FIELD} characters)")
        out[str(key)] = value.strip()
    return out


def _number(form: dict[str, str], key: str, unit: str) -> float:
    """A field the page sends as "<number> <unit>" with this unit (a range bound, the
    squeeze); a number without its unit is refused (a squeeze of "0.12" is not 12 %)."""
    text = form.get(key, "")
    number, _, given = text.partition(" ")
    try:
        value = float(number)
    except ValueError:
        raise InputError(f"{key}: {text!r} is not a number in {unit}") from None
    if given.strip() != unit or not math.isfinite(value):
        raise InputError(f"{key}: {text!r} must be a finite number followed by the unit "
                         f"{unit!r}")
    return value


def _require(form: dict[str, str], *keys: str) -> None:
    """Refuse a form without one of these fields (the page leaves an emptied field out)."""
    for key in keys:
        if not form.get(key):
            raise InputError(f"{key}: required")


def _lip_arguments(form: dict[str, str]) -> dict[str, Any]:
    """Arguments of :func:`sealsim.lip_seal_torque` from the page's form (unit strings)."""
    _require(form, "shaft_diameter", "speed", "oil", "material", "lip_style")
    return {"shaft_diameter": form["shaft_diameter"], "speed": form["speed"],
            "oil": form["oil"], "sump_temperature": form.get("sump_temperature") or None,
            "material": form["material"], "lip_style": form["lip_style"],
            "ambient_temperature": form.get("ambient_temperature") or "20 degC"}


def rotary_case_toml(args: dict[str, Any]) -> str:
    """The rotary case file equivalent to a lip-seal calculation: the same seal, oil and
    environment, held at the speed until the temperatures are steady (``sealsim rotary run``
    then ends at the steady operating point the calculator shows)."""
    import tomli_w

    from sealsim.cases import validate_case
    from sealsim.rotary.case import RotaryCase

    environment = {"ambient_temperature": args["ambient_temperature"]}
    if args["sump_temperature"] is not None:
        environment["sump_temperature"] = args["sump_temperature"]
    data = {"title": f"Lip seal {args['shaft_diameter']}, {args['speed']}, {args['oil']} "
                     "(from sealsim app)",
            "seal": {"shaft_diameter": args["shaft_diameter"], "material": args["material"],
                     "lip_style": args["lip_style"]},
            "oil": {"name": args["oil"]},
            "environment": environment,
            "duty": {"steps": [{"speed": args["speed"], "duration": "10 min"}],
                     "until_steady": True, "steady_rate": APP_STEADY_RATE}}
    validate_case(RotaryCase, data, "rotary case")  # the file the page offers must run
    header = ("# Written by sealsim app: the lip-seal calculation as a rotary case.\n"
              "#   sealsim rotary run lip_seal.toml --out results/lip_seal\n"
              "# holds the speed until the temperatures are steady; the end of the run is the\n"
              "# operating point the page showed.\n\n")
    return header + tomli_w.dumps(data)


def _gland_case(req):
    """The validated gland case of a request (its TOML text)."""
    from sealsim.cases import validate_case
    from sealsim.structure.gland_case import GlandCase

    return validate_case(GlandCase, _gland_tables(req.get_json(silent=True)), "gland")


def _gland_tables(data) -> dict[str, Any]:
    """The gland case tables from the page (its TOML text)."""
    if not isinstance(data, dict) or not isinstance(data.get("toml"), str):
        raise InputError("the request holds no gland case (TOML text)")
    if len(data["toml"]) > 64 * 1024:
        raise InputError("gland case: longer than 64 kB")
    try:
        return tomllib.loads(data["toml"])
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"gland case is not valid TOML: {exc}") from None


def _png_data(png: bytes) -> str:
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


def _json(data):
    from sealsim.output import json_ready

    return jsonify(json_ready(data))
