"""``sealsim app`` driven in a real headless Chromium (Debian's ``chromium`` and
``chromium-driver``, through Selenium): every number on a page is the API's number, the gland
page names the failed check, a broken upload shows the command line's error, two tabs keep
their runs apart.  One server and one browser per test session (the tests share the xdist
group "browser").  Screenshots go to a scratch folder; with
``SEALSIM_APP_SCREENSHOTS=docs/_static/app`` they refresh the documentation's app page.
"""

from __future__ import annotations

import io
import json
import os
import shutil
import tempfile
import urllib.request
import zipfile
from pathlib import Path

import pytest
from typer.testing import CliRunner

import sealsim
from sealsim.cli import app as cli

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
# Screenshots for the documentation's app page are refreshed on request only
# (SEALSIM_APP_SCREENSHOTS=docs/_static/app pytest tests/test_app.py), so that a test run does
# not rewrite tracked files; otherwise they go to a scratch folder (still taken: a failing
# screenshot is a failing page).
SHOTS = Path(os.environ.get("SEALSIM_APP_SCREENSHOTS") or
             Path(tempfile.gettempdir()) / "sealsim-app-screenshots")
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
DRIVER = shutil.which("chromedriver")
WAIT = 90  # s: a case run starts a fresh Python process on a busy 2-core machine

pytestmark = pytest.mark.xdist_group("browser")


@pytest.fixture(scope="session")
def server(tmp_path_factory):
    from sealsim.app import start_server

    server, url = start_server(run_timeout=300,
                               work_dir=tmp_path_factory.mktemp("app") / "jobs")
    yield url
    server.shutdown()
    server.app.extensions["sealsim_jobs"].close()


@pytest.fixture(scope="session")
def browser():
    if not (CHROMIUM and DRIVER):
        message = ("the browser tests need Debian's chromium and chromium-driver "
                   "(apt-get install chromium chromium-driver; .ci/run installs them)")
        if os.environ.get("CI"):
            pytest.fail(message)      # CI must run them, never skip
        pytest.skip(message)
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for arg in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
                "--window-size=1300,1500", "--disable-gpu"):
        options.add_argument(arg)
    driver = webdriver.Chrome(service=Service(DRIVER), options=options)
    yield driver
    driver.quit()


def _wait(driver, condition, timeout=WAIT):
    from selenium.webdriver.support.ui import WebDriverWait

    return WebDriverWait(driver, timeout, poll_frequency=0.2).until(condition)


def _visible(element_id):
    return lambda d: (d.find_element("id", element_id).is_displayed()
                      and d.find_element("id", element_id))


def _shot(driver, name):
    SHOTS.mkdir(parents=True, exist_ok=True)
    driver.save_screenshot(str(SHOTS / f"{name}.png"))


def _open(driver, url, tab):
    driver.get(url)
    _wait(driver, lambda d: d.find_elements("css selector", "#lip-oil option"))
    driver.find_element("id", f"tab-{tab}").click()


def _set(driver, element_id, value):
    from selenium.webdriver.support.ui import Select

    element = driver.find_element("id", element_id)
    if element.tag_name == "select":
        Select(element).select_by_value(value)
    else:
        element.clear()
        element.send_keys(value)


def test_an_uploaded_case_that_refers_to_another_file_is_told_to_use_the_command_line(
        tmp_path, monkeypatch):
    # the upload runs alone in its folder: "duty.csv file 'duty.csv' does not exist" left the
    # user to guess why a file next to their case was not found
    from sealsim.app.jobs import CASE_FILE, _run_case
    from sealsim.errors import InputError

    monkeypatch.chdir(tmp_path)          # _run_case enters the job's folder; restored after
    (tmp_path / CASE_FILE).write_text('[seal]\nshaft_diameter = "80 mm"\n'
                                      '[duty]\ncsv = "duty.csv"\n')
    with pytest.raises(InputError, match=r"duty.csv' does not exist \(the app runs an uploaded "
                                         r"case alone.*sealsim rotary run case.toml --out DIR"):
        _run_case(tmp_path, None)


@pytest.mark.parametrize("host, problem", [
    ("999.1.1.1", "is not an IP address nor a host name that resolves"),
    ("192.0.2.1", "is not an address of this computer"),     # TEST-NET-1: never local
])
def test_a_host_the_server_cannot_listen_on_is_refused_before_it_starts(host, problem):
    # werkzeug printed only "Name or service not known" and exited by itself
    result = CliRunner().invoke(cli, ["app", "--host", host, "--no-browser"])
    message = " ".join(result.output.split())
    assert result.exit_code == 2, message
    assert f"--host '{host}' {problem}" in message
    assert "give an IP address or host name of this computer, e.g. 127.0.0.1" in message


def test_the_announced_address_of_an_ipv6_host_opens(tmp_path):
    # `sealsim app --host ::1` announced http://::1:PORT/, which no browser opens: an IPv6
    # literal goes in brackets (RFC 3986); the announced address must serve the app
    import socket
    import urllib.request

    from sealsim.app import server_url, start_server

    assert server_url("::1", 8050) == "http://[::1]:8050/"
    assert server_url("127.0.0.1", 8050) == "http://127.0.0.1:8050/"
    if not socket.has_ipv6:
        pytest.skip("this machine has no IPv6")
    from sealsim.errors import InputError

    try:
        server, url = start_server(host="::1", port=0, work_dir=tmp_path / "jobs")
    except (OSError, InputError):
        pytest.skip("no IPv6 loopback here")
    try:
        assert url.startswith("http://[::1]:")
        assert urllib.request.urlopen(url, timeout=30).status == 200
    finally:
        server.shutdown()
        server.app.extensions["sealsim_jobs"].close()


@pytest.mark.filterwarnings("ignore::sealsim.tribology.film.FilmRangeWarning")
def test_the_lip_seal_pages_case_file_ends_at_the_pages_operating_point():
    # The page offers its calculation as a rotary case held until steady.  With a free sump
    # (time constant about an hour) the default steady_rate of 0.05 K/min stopped the run
    # 2.1 K short of the page's contact temperature and 2.3 K short of its sump (60 mm, VG 68,
    # 1500 rpm); the case asks for 0.005 K/min: within 0.2 K (measured with 4 s steps).
    import tomllib

    from sealsim.app.server import rotary_case_toml
    from sealsim.cases import apply_overrides, validate_case
    from sealsim.rotary.case import RotaryCase
    from sealsim.rotary.simulation import simulate

    args = {"shaft_diameter": "60 mm", "speed": "1500 rpm", "oil": "VG68-mineral",
            "sump_temperature": None, "material": "NBR", "lip_style": "plain",
            "ambient_temperature": "20 degC"}
    page = sealsim.lip_seal_torque(**args)
    data = tomllib.loads(rotary_case_toml(args))
    case = validate_case(RotaryCase, apply_overrides(data, {"numerics": {
        "max_time_step": "30 s"}}))
    last = simulate(case).timeseries.iloc[-1]
    assert last["T_contact_C"] == pytest.approx(page["T_contact_C"], abs=0.5)
    assert last["T_sump_C"] == pytest.approx(page["T_sump_C"], abs=0.5)
    assert last["torque_Nm"] == pytest.approx(page["torque_Nm"], rel=0.005)


def test_lip_seal_page_shows_the_api_torque(server, browser):
    _open(browser, server, "lip")
    for element_id, value in (("lip-diameter", "60"), ("lip-speed", "2000"),
                              ("lip-oil", "VG220-mineral"), ("lip-sump-mode", "held"),
                              ("lip-sump", "70"), ("lip-ambient", "25"),
                              ("lip-material", "FKM"), ("lip-style", "wave")):
        _set(browser, element_id, value)
    browser.find_element("id", "lip-run").click()
    torque = _wait(browser, _visible("lip-torque"))
    expected = sealsim.lip_seal_torque("60 mm", "2000 rpm", "VG220-mineral", "70 degC",
                                       material="FKM", lip_style="wave",
                                       ambient_temperature="25 degC")
    # the page keeps the API's number (data-value, JSON round trip: exact) and shows it
    # to 4 significant digits
    assert float(torque.get_attribute("data-value")) == expected["torque_Nm"]
    assert float(torque.text) == pytest.approx(expected["torque_Nm"], rel=5e-4)
    contact = browser.find_element("id", "lip-tcontact")
    assert float(contact.get_attribute("data-value")) == expected["T_contact_C"]
    for element_id, key in (("lip-heat-oil", "heat_oil_side_W"),
                            ("lip-heat-housing", "heat_housing_W"),
                            ("lip-heat-air", "heat_air_side_W")):
        assert float(browser.find_element("id", element_id).get_attribute("data-value")) \
            == expected[key], key
    assert browser.find_element("id", "lip-notes").find_elements("tag name", "li")
    _wait(browser, _visible("lip-curve"))
    # the download is a rotary case that validates and names the same operating point
    text = browser.execute_async_script(
        "const done = arguments[0];"
        "fetch(document.getElementById('lip-download').href).then(r => r.text()).then(done);")
    import tomllib

    from sealsim.cases import validate_case
    from sealsim.rotary.case import RotaryCase

    case = validate_case(RotaryCase, tomllib.loads(text), "downloaded case")
    assert case.seal.lip_style == "wave" and case.duty.steps[0].speed * 30 / 3.141592653589793 \
        == pytest.approx(2000.0)
    _shot(browser, "lip_seal")


def test_gland_page_names_the_failed_check_of_an_example(server, browser):
    _open(browser, server, "gland")
    _set(browser, "gland-example", "rod_extrusion_fails")
    browser.find_element("id", "gland-load").click()
    _wait(browser, lambda d: "H11" in d.find_element("id", "gland-toml").get_attribute("value"))
    browser.find_element("id", "gland-check").click()
    _wait(browser, _visible("gland-result"))
    assert browser.find_element("id", "gland-failed").text == "extrusion_gap"
    row = browser.find_element("css selector", "#gland-checks tr[data-name='extrusion_gap']")
    assert row.get_attribute("class") == "fail"
    # values and limits with their units, the checks named as the CLI prints them (the table
    # had no units and headed the values "worst case", also for stretch_min at assembly)
    cells = [c.text for c in row.find_elements("css selector", "td")]
    assert cells[2].endswith(" mm") and cells[3].startswith("≤ ") and cells[3].endswith(" mm")
    squeeze = browser.find_element("css selector", "#gland-checks tr[data-name='squeeze_min']")
    assert squeeze.find_elements("css selector", "td")[2].text.endswith(" %")
    expected = sealsim.oring_gland(EXAMPLES / "gland" / "rod_extrusion_fails.toml")
    cell = browser.find_element("id", "gland-squeeze_percent-min")
    assert float(cell.get_attribute("data-value")) == expected["squeeze_percent"]["min"]
    notes = browser.find_element("id", "gland-notes").text
    assert "extrusion_gap fails" in notes
    _wait(browser, _visible("gland-figure"))
    _shot(browser, "gland")


def test_broken_upload_shows_the_command_lines_error(server, browser, tmp_path,
                                                     monkeypatch):
    broken = (EXAMPLES / "rotary" / "speed_cycle.toml").read_text().replace(
        'shaft_diameter = "80 mm"', 'shaft_diameter = "80 kg"')
    (tmp_path / "case.toml").write_text(broken)
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(cli, ["rotary", "run", "case.toml", "--out", "out"])
    assert result.exit_code == 2
    cli_message = " ".join(result.output.split())
    upload = tmp_path / "my broken case (copy).toml"   # the name never becomes a path
    upload.write_text(broken)
    _open(browser, server, "run")
    browser.find_element("id", "run-file").send_keys(str(upload))
    browser.find_element("id", "run-start").click()
    error = _wait(browser, _visible("run-error"))
    assert " ".join(error.text.split()) == cli_message
    assert "80 kg" in cli_message
    _shot(browser, "run_error")


def test_two_tabs_run_cases_and_see_only_their_own_results(server, browser, tmp_path):
    cases = {"gland": EXAMPLES / "gland" / "piston_static.toml",
             "friction": EXAMPLES / "friction" / "lugre_presliding.toml"}
    first = browser.current_window_handle
    browser.switch_to.new_window("tab")
    second = browser.current_window_handle
    for handle, path in zip((first, second), cases.values()):
        browser.switch_to.window(handle)
        _open(browser, server, "run")
        browser.find_element("id", "run-file").send_keys(str(path))
        browser.find_element("id", "run-start").click()
    files, zips = {}, {}
    for handle, kind in zip((first, second), cases):
        browser.switch_to.window(handle)
        _wait(browser, _visible("run-zip"))
        files[kind] = [a.text for a in browser.find_elements("css selector", "#run-files a")]
        zips[kind] = browser.find_element("id", "run-zip").get_attribute("href")
        if kind == "gland":
            _shot(browser, "run_case")
    assert "section.png" in files["gland"] and "force_velocity.png" not in files["gland"]
    # the result folder's marker (bookkeeping of --force) is no result to download
    assert not any(".sealsim-results" in name for names in files.values() for name in names)
    assert "force_velocity.png" in files["friction"] and "section.png" not in files["friction"]
    assert zips["gland"] != zips["friction"]
    with urllib.request.urlopen(zips["gland"]) as response:
        archive = zipfile.ZipFile(io.BytesIO(response.read()))
    report = json.loads(archive.read("result/report.json"))
    assert report["title"].startswith("Static piston gland")
    # the plots are the run's own files, shown on the page
    images = browser.find_elements("css selector", "#run-plots img")
    assert images and all(img.get_attribute("naturalWidth") != "0" for img in images)
    browser.close()
    browser.switch_to.window(first)


def test_friction_page_shows_the_api_numbers(server, browser):
    _open(browser, server, "friction")
    browser.find_element("id", "fr-run").click()
    force = _wait(browser, _visible("fr-fn"))
    expected = sealsim.seal_friction({"cord_diameter": "2 mm", "squeeze": 0.12,
                                      "elastomer": "NBR"}, "0.001 m/s", "6 bar", "20 degC",
                                     law={"law": "lugre", "parameter_set": "canudas1995"},
                                     diameter="12 mm")
    assert float(force.get_attribute("data-value")) == expected["normal_force_N"]
    _wait(browser, lambda d: d.find_element("id", "fr-figure").get_attribute("naturalWidth")
          not in (None, "0"))
    _shot(browser, "friction")


@pytest.mark.slow
def test_gland_fe_runs_with_progress(server, browser):
    _open(browser, server, "gland")
    _set(browser, "gland-example", "rod_reciprocating")
    browser.find_element("id", "gland-load").click()
    _wait(browser, lambda d: "[fe]" in d.find_element("id", "gland-toml").get_attribute("value"))
    browser.find_element("id", "gland-fe").click()
    cell = _wait(browser, _visible("fe-fn0"), timeout=300)
    assert float(cell.get_attribute("data-value")) > 0


@pytest.fixture
def client(tmp_path):
    """The app's endpoints without a browser (Flask's test client)."""
    from sealsim.app.server import AppConfig, create_app

    flask_app = create_app(AppConfig(tmp_path / "jobs"))
    yield flask_app.test_client()
    flask_app.extensions["sealsim_jobs"].close()


FRICTION_FORM = {"cord_diameter": "2 mm", "squeeze": "12 %", "elastomer": "NBR",
                 "law": "coulomb", "parameter_set": "unit", "pressure": "6 bar",
                 "temperature": "25 degC", "diameter": "32 mm", "velocity_min": "0.001 m/s",
                 "velocity_max": "1 m/s", "amplitude": "5 mm/s", "frequency": "1 Hz",
                 "mean_velocity": "0 mm/s"}


@pytest.mark.parametrize("field", ["cord_diameter", "pressure", "amplitude"])
def test_the_friction_page_names_a_field_left_empty(client, field):
    # The page leaves an emptied field out of its form; the server looked it up and answered
    # with a 500 "Internal Server Error" page (KeyError) instead of naming the field.
    form = {k: v for k, v in FRICTION_FORM.items() if k != field}
    response = client.post("/api/friction", json=form)
    assert response.status_code == 400
    assert response.get_json() == {"error": f"input error: {field}: required"}


@pytest.mark.parametrize(("url", "field", "text"), [
    ("/api/friction", "squeeze", "0.12"),            # was taken as 0.12 %
    ("/api/friction", "velocity_max", "1"),
    ("/api/lip-seal/curve", "speed_max", "3000"),
])
def test_a_range_or_squeeze_without_its_unit_is_refused(client, url, field, text):
    # The page sends "<number> <unit>"; a bare number was read in the page's unit, so a
    # squeeze of "0.12" (a fraction, as case files write it) silently became 0.12 %.
    lip = {"shaft_diameter": "80 mm", "speed": "1500 rpm", "oil": "VG68-mineral",
           "material": "NBR", "lip_style": "plain", "sump_temperature": "60 degC",
           "speed_min": "0 rpm", "speed_max": "3000 rpm"}
    form = {**(FRICTION_FORM if url == "/api/friction" else lip), field: text}
    response = client.post(url, json=form)
    assert response.status_code == 400
    error = response.get_json()["error"]
    assert error.startswith(f"input error: {field}: {text!r} must be a finite number "
                            "followed by the unit"), error
