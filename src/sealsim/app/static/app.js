// sealsim app: forms -> JSON endpoints -> the API's numbers.  No physics here.
"use strict";

const $ = (id) => document.getElementById(id);

// every number shown keeps the API's full value in data-value
function show(id, value, digits = 4) {
  const el = $(id);
  el.dataset.value = String(value);
  el.textContent = Number(value).toPrecision(digits);
}

function showError(id, message) {
  const el = $(id);
  el.textContent = message || "";
  el.hidden = !message;
}

function fillNotes(id, notes) {
  const list = $(id);
  list.replaceChildren();
  for (const note of notes.length ? notes : ["none"]) {
    const li = document.createElement("li");
    li.textContent = note;
    list.appendChild(li);
  }
}

async function post(url, body) {
  const response = await fetch(url, {method: "POST", headers: {"Content-Type": "application/json"},
                                     body: JSON.stringify(body)});
  const data = await response.json();
  if (!response.ok) throw new Error(data.error || response.statusText);
  return data;
}

function quantity(id, unit) {
  const text = $(id).value.trim();
  return text === "" ? null : `${text} ${unit}`;
}

function fillSelect(id, items, selected) {
  const select = $(id);
  select.replaceChildren();
  for (const [value, label] of items) {
    const option = document.createElement("option");
    option.value = value;
    option.textContent = label;
    if (value === selected) option.selected = true;
    select.appendChild(option);
  }
}

// -- tabs ---------------------------------------------------------------------------------
for (const tab of document.querySelectorAll(".tab")) {
  tab.addEventListener("click", () => {
    for (const other of document.querySelectorAll(".tab")) other.classList.remove("active");
    tab.classList.add("active");
    for (const page of document.querySelectorAll(".page")) {
      page.hidden = page.id !== `page-${tab.dataset.page}`;
    }
  });
}

// -- options ------------------------------------------------------------------------------
async function loadOptions() {
  const options = await (await fetch("/api/options")).json();
  fillSelect("lip-oil", options.oils.map((o) => [o, o]), "VG68-mineral");
  fillSelect("lip-material", options.materials.map((m) => [m, m]), "NBR");
  fillSelect("fr-elastomer", options.materials.map((m) => [m, m]), "NBR");
  const laws = [];
  for (const [law, sets] of Object.entries(options.laws)) {
    for (const set of sets) laws.push([`${law}|${set}`, `${law} (${set})`]);
  }
  fillSelect("fr-law", laws, "lugre|canudas1995");
  fillSelect("gland-example", options.gland_examples.map((n) => [n, n]), "piston_static");
  $("run-limit-kb").textContent = options.limits.upload_kB;
  $("run-limit-s").textContent = options.limits.run_timeout_s;
  if (options.gland_examples.length) await loadGlandExample();
}

// -- lip seal -----------------------------------------------------------------------------
function lipForm() {
  return {
    shaft_diameter: quantity("lip-diameter", "mm"),
    speed: quantity("lip-speed", "rpm"),
    speed_min: quantity("lip-speed-min", "rpm"),
    speed_max: quantity("lip-speed-max", "rpm"),
    oil: $("lip-oil").value,
    sump_temperature: $("lip-sump-mode").value === "held" ? quantity("lip-sump", "degC") : null,
    ambient_temperature: quantity("lip-ambient", "degC"),
    material: $("lip-material").value,
    lip_style: $("lip-style").value,
  };
}

$("lip-sump-mode").addEventListener("change", () => {
  $("lip-sump").disabled = $("lip-sump-mode").value !== "held";
});

$("lip-form").addEventListener("submit", async (event) => {
  event.preventDefault();
  showError("lip-error", "");
  $("lip-result").hidden = true;
  const form = lipForm();
  let data;
  try {
    data = await post("/api/lip-seal", form);
  } catch (error) {
    showError("lip-error", error.message);
    return;
  }
  const p = data.point;
  show("lip-torque", p.torque_Nm);
  show("lip-power", p.power_W);
  show("lip-tcontact", p.T_contact_C);
  show("lip-tsump", p.T_sump_C);
  show("lip-film", p.film_um, 3);
  show("lip-heat-oil", p.heat_oil_side_W, 3);
  show("lip-heat-housing", p.heat_housing_W, 3);
  show("lip-heat-air", p.heat_air_side_W, 3);
  fillNotes("lip-notes", data.notes);
  const blob = new Blob([data.case_toml], {type: "application/toml"});
  $("lip-download").href = URL.createObjectURL(blob);
  $("lip-result").hidden = false;
  $("lip-curve").hidden = true;
  $("lip-curve-busy").hidden = false;
  try {
    const curve = await post("/api/lip-seal/curve", form);
    $("lip-curve").src = curve.figure;
    $("lip-curve").hidden = false;
    fillNotes("lip-notes", [...new Set([...data.notes, ...curve.notes])]);
  } catch (error) {
    showError("lip-error", error.message);
  } finally {
    $("lip-curve-busy").hidden = true;
  }
});

// -- O-ring gland -------------------------------------------------------------------------
async function loadGlandExample() {
  const name = $("gland-example").value;
  const response = await fetch(`/api/gland/example/${encodeURIComponent(name)}`);
  const data = await response.json();
  if (response.ok) $("gland-toml").value = data.toml;
}
$("gland-load").addEventListener("click", loadGlandExample);

function fillStack(report) {
  const table = $("gland-stack");
  table.replaceChildren();
  const head = table.insertRow();
  for (const text of ["worst-case stack", "min", "nominal", "max"]) {
    const th = document.createElement("th");
    th.textContent = text;
    head.appendChild(th);
  }
  const rows = [["squeeze_percent", "squeeze [%]"], ["stretch_percent", "stretch [%]"],
                ["gland_fill_percent", "gland fill [%]"], ["extrusion_gap_mm", "extrusion gap [mm]"]];
  for (const [key, label] of rows) {
    const row = table.insertRow();
    row.insertCell().textContent = label;
    for (const which of ["min", "nominal", "max"]) {
      const cell = row.insertCell();
      cell.id = `gland-${key}-${which}`;
      cell.dataset.value = String(report[key][which]);
      cell.textContent = Number(report[key][which]).toPrecision(4);
    }
  }
}

function fillChecks(checks) {
  const table = $("gland-checks");
  table.replaceChildren();
  const head = table.insertRow();
  for (const text of ["", "check", "value", "limit", "source"]) {
    const th = document.createElement("th");
    th.textContent = text;
    head.appendChild(th);
  }
  for (const check of checks) {
    const row = table.insertRow();
    row.className = check.ok ? "ok" : "fail";
    row.dataset.name = check.name;
    row.insertCell().textContent = check.ok ? "ok" : "FAIL";
    row.insertCell().textContent = check.label;
    const value = row.insertCell();
    value.dataset.value = String(check.value);
    value.textContent = `${Number(check.value).toPrecision(4)} ${check.unit}`;
    row.insertCell().textContent = `${check.bound === "min" ? "≥" : "≤"} ${Number(check.limit).toPrecision(4)} ${check.unit}`;
    row.insertCell().textContent = check.source + (check.maker ? " (a seal maker's recommendation)" : "");
  }
}

$("gland-check").addEventListener("click", async () => {
  showError("gland-error", "");
  $("gland-result").hidden = true;
  let data;
  try {
    data = await post("/api/gland", {toml: $("gland-toml").value});
  } catch (error) {
    showError("gland-error", error.message);
    return;
  }
  const report = data.report;
  $("gland-verdict").textContent = report.ok ? "All checks pass" : "The gland fails";
  $("gland-verdict").className = report.ok ? "verdict ok" : "verdict fail";
  $("gland-failed").textContent = report.failed.length ? report.failed.join(", ") : "none";
  fillStack(report);
  fillChecks(report.checks);
  fillNotes("gland-notes", data.notes);
  $("gland-figure").hidden = true;
  $("gland-result").hidden = false;
  try {
    const picture = await post("/api/gland/figure", {toml: $("gland-toml").value});
    $("gland-figure").src = picture.figure;
    $("gland-figure").hidden = false;
  } catch (error) {
    showError("gland-error", error.message);
  }
});

async function poll(token, onProgress) {
  for (;;) {
    const response = await fetch(`/api/jobs/${token}`);
    const job = await response.json();
    if (!response.ok) throw new Error(job.error || response.statusText);
    if (job.state !== "running") return job;
    onProgress(job);
    await new Promise((resolve) => setTimeout(resolve, 500));
  }
}

function progressText(job) {
  return job.total > 0 ? `${job.label} ${Math.round(job.done)}/${Math.round(job.total)}, ${job.elapsed_s} s`
                       : `starting ... ${job.elapsed_s} s`;
}

$("gland-fe").addEventListener("click", async () => {
  showError("gland-error", "");
  const box = $("gland-fe-box");
  box.hidden = false;
  $("gland-fe-result").replaceChildren();
  $("gland-fe-notes").replaceChildren();
  const bar = $("gland-fe-progress");
  bar.removeAttribute("value");
  $("gland-fe-status").textContent = "starting the FE model ...";
  try {
    const {token} = await post("/api/gland/fe", {toml: $("gland-toml").value});
    const job = await poll(token, (j) => {
      if (j.total > 0) { bar.max = j.total; bar.value = j.done; }
      $("gland-fe-status").textContent = progressText(j);
    });
    if (job.state !== "done") throw new Error(job.error);
    bar.max = 1; bar.value = 1;
    $("gland-fe-status").textContent = `done in ${job.elapsed_s} s`;
    const fe = job.result.fe;
    const rows = [["squeeze at nominal [%]", fe.squeeze_percent, "fe-squeeze"],
                  ["normal force F_N, unpressurised [N]", fe.normal_force_N.unpressurised, "fe-fn0"],
                  [`normal force F_N at ${fe.pressure_bar} bar [N]`, fe.normal_force_N.at_pressure, "fe-fnp"],
                  ["contact width, unpressurised [mm]", fe.contact_width_mm.unpressurised, "fe-b0"],
                  [`friction at ${fe.velocity_m_s} m/s, unpressurised, outstroke [N]`, fe.friction_N.outstroke.unpressurised, "fe-f0"],
                  [`friction at ${fe.velocity_m_s} m/s, unpressurised, instroke [N]`, fe.friction_N.instroke.unpressurised, "fe-f0-in"],
                  [`friction at ${fe.velocity_m_s} m/s and ${fe.pressure_bar} bar, outstroke [N]`, fe.friction_N.outstroke.at_pressure, "fe-fp"],
                  [`friction at ${fe.velocity_m_s} m/s and ${fe.pressure_bar} bar, instroke [N]`, fe.friction_N.instroke.at_pressure, "fe-fp-in"]];
    for (const [label, value, id] of rows) {
      const row = $("gland-fe-result").insertRow();
      row.insertCell().textContent = label;
      const cell = row.insertCell();
      cell.id = id;
      cell.dataset.value = String(value);
      cell.textContent = Number(value).toPrecision(4);
    }
    fillNotes("gland-fe-notes", [`friction law: ${JSON.stringify(fe.law)}`, ...fe.notes]);
  } catch (error) {
    $("gland-fe-status").textContent = "";
    showError("gland-error", error.message);
  }
});

// -- friction -----------------------------------------------------------------------------
$("friction-form").addEventListener("submit", async (event) => {
  event.preventDefault();
  showError("fr-error", "");
  $("fr-result").hidden = true;
  const [law, set] = $("fr-law").value.split("|");
  const form = {
    cord_diameter: quantity("fr-cord", "mm"), squeeze: quantity("fr-squeeze", "%"),
    diameter: quantity("fr-diameter", "mm"), elastomer: $("fr-elastomer").value,
    pressure: quantity("fr-pressure", "bar"), temperature: quantity("fr-temperature", "degC"),
    law: law, parameter_set: set,
    velocity_min: quantity("fr-vmin", "m/s"), velocity_max: quantity("fr-vmax", "m/s"),
    amplitude: quantity("fr-amplitude", "mm/s"), mean_velocity: quantity("fr-mean", "mm/s"),
    frequency: quantity("fr-frequency", "Hz"),
  };
  try {
    const data = await post("/api/friction", form);
    show("fr-fn", data.normal_force_N);
    show("fr-b", data.contact_width_mm);
    $("fr-loop").textContent = `${Number(data.loop_last_cycle.friction_min_N).toPrecision(4)} ... ${Number(data.loop_last_cycle.friction_max_N).toPrecision(4)}`;
    $("fr-figure").src = data.figure;
    fillNotes("fr-notes", data.notes);
    $("fr-result").hidden = false;
  } catch (error) {
    showError("fr-error", error.message);
  }
});

// -- run a case ---------------------------------------------------------------------------
$("run-form").addEventListener("submit", async (event) => {
  event.preventDefault();
  showError("run-error", "");
  const file = $("run-file").files[0];
  if (!file) { showError("run-error", "choose a case file first"); return; }
  $("run-box").hidden = false;
  $("run-zip").hidden = true;
  $("run-files").replaceChildren();
  $("run-plots").replaceChildren();
  const bar = $("run-progress");
  bar.removeAttribute("value");
  $("run-status").textContent = "uploading ...";
  const body = new FormData();
  body.append("case", file);
  try {
    const response = await fetch("/api/run", {method: "POST", body});
    const started = await response.json();
    if (!response.ok) throw new Error(started.error || response.statusText);
    const job = await poll(started.token, (j) => {
      if (j.total > 0) { bar.max = j.total; bar.value = j.done; }
      $("run-status").textContent = progressText(j);
    });
    if (job.state !== "done") throw new Error(job.error);
    bar.max = 1; bar.value = 1;
    $("run-status").textContent = `${job.result.command}: done in ${job.elapsed_s} s`;
    const base = `/api/jobs/${started.token}`;
    $("run-zip").href = `${base}/result.zip`;
    $("run-zip").hidden = false;
    for (const name of job.files) {
      const li = document.createElement("li");
      const a = document.createElement("a");
      a.href = `${base}/file/${name}`;
      a.textContent = name;
      li.appendChild(a);
      $("run-files").appendChild(li);
      if (name.endsWith(".png")) {
        const img = document.createElement("img");
        img.src = `${base}/file/${name}`;
        img.alt = name;
        img.className = "run-plot";
        $("run-plots").appendChild(img);
      }
    }
  } catch (error) {
    bar.value = 0;
    $("run-status").textContent = "";
    showError("run-error", error.message);
  }
});

loadOptions();
