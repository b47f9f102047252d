"""Benchmark of ``sealsim app``'s calculators: the time from the page's request to the answer
(targets in brackets).

The app's server runs in this process (:func:`sealsim.app.start_server`, port 0); requests go
over HTTP on 127.0.0.1 as the page sends them, after the server's warm-up (numba kernels,
matplotlib):

1. the lip-seal answer (``POST /api/lip-seal``: torque, power, temperatures, film and the
   equivalent case file) [< 1 s];
2. the gland check (``POST /api/gland``: worst-case stack and checks) of
   examples/gland/rod_extrusion_fails.toml [< 1 s];
3. the pictures the page loads after the answers (no target; shown for scale): the lip-seal
   curves over speed (``POST /api/lip-seal/curve``, 12 speeds and the figure) and the gland
   section (``POST /api/gland/figure``).

Baseline in the same process: the API call alone (``sealsim.lip_seal_torque``,
``sealsim.oring_gland``), so the ratio shows what the server and JSON add.  Each time is
the median of 7 requests (3 for the pictures).  The last line is one JSON object with
lip_seal_s, gland_s, lip_seal_curve_s, gland_figure_s, lip_seal_api_s, gland_api_s,
cold_lip_seal_s (the first request after start, before the warm-up finished) and
targets_met.
"""

import json
import statistics
import time
import urllib.request
from pathlib import Path

import sealsim
from sealsim.app import start_server

GLAND = Path(__file__).resolve().parents[1] / "examples" / "gland" / "rod_extrusion_fails.toml"
LIP = {"shaft_diameter": "80 mm", "speed": "1500 rpm", "speed_min": "100 rpm",
       "speed_max": "3000 rpm", "oil": "VG68-mineral", "sump_temperature": "80 degC",
       "ambient_temperature": "20 degC", "material": "NBR", "lip_style": "plain"}


def post(url, body):
    request = urllib.request.Request(url, data=json.dumps(body).encode(),
                                     headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(request) as response:
        return json.load(response)


def median_time(function, repeat=7):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main():
    server, url = start_server()
    start = time.perf_counter()
    post(url + "api/lip-seal", LIP)
    cold = time.perf_counter() - start
    gland = {"toml": GLAND.read_text()}
    post(url + "api/gland/figure", gland)              # first gland figure: imports
    lip_s = median_time(lambda: post(url + "api/lip-seal", LIP))
    gland_s = median_time(lambda: post(url + "api/gland", gland))
    curve_s = median_time(lambda: post(url + "api/lip-seal/curve", LIP), repeat=3)
    picture_s = median_time(lambda: post(url + "api/gland/figure", gland), repeat=3)
    lip_api = median_time(lambda: sealsim.lip_seal_torque(
        "80 mm", "1500 rpm", "VG68-mineral", "80 degC", material="NBR", lip_style="plain",
        ambient_temperature="20 degC"))
    gland_api = median_time(lambda: sealsim.oring_gland(GLAND))
    server.shutdown()
    server.app.extensions["sealsim_jobs"].close()
    print(f"lip-seal answer : {lip_s:.3f} s per request (API alone {lip_api:.3f} s, "
          f"x{lip_s / lip_api:.1f}); first request after start {cold:.2f} s")
    print(f"gland check     : {gland_s:.3f} s per request (API alone {gland_api:.3f} s, "
          f"x{gland_s / gland_api:.1f})")
    print(f"pictures loaded after the answers: lip-seal curves {curve_s:.3f} s (12 speeds and "
          f"the figure), gland section {picture_s:.3f} s")
    met = lip_s < 1.0 and gland_s < 1.0
    print(f"targets (< 1 s each): {'met' if met else 'NOT met'}")
    print(json.dumps({"lip_seal_s": round(lip_s, 4), "gland_s": round(gland_s, 4),
                      "lip_seal_curve_s": round(curve_s, 4), "gland_figure_s": round(picture_s, 4),
                      "lip_seal_api_s": round(lip_api, 4),
                      "gland_api_s": round(gland_api, 4), "cold_lip_seal_s": round(cold, 3),
                      "targets_met": met}))


if __name__ == "__main__":
    main()
