// The scatterlab explorer's page (docs/explorer.md): the material list, inputs generated from the
// registry's parameter specs, the incident direction, and the four views, all computed by the
// model code compiled to WebAssembly (scatterlab-api.js) and drawn by explorer-plots.js.
(function () {
  'use strict';

  const { build, evalPairs, drawSamples, albedoCurve, fileSystem } = window.scatterlabKernels;
  const { radians, direction, diskPoint, diskPairs, mean3, format, drawLobe, drawDisks, markDirection, drawAlbedo } =
    window.scatterlabPlots;
  const api = window.scatterlab;

  const $ = (id) => document.getElementById(id);
  const errorBox = $('error-box');

  function showError(message) {
    errorBox.textContent = message;
    errorBox.hidden = false;
  }
  function hideError() {
    errorBox.hidden = true;
    errorBox.textContent = '';
  }
  // Nothing may leave the page blank: any error ends in the error box.
  window.addEventListener('error', (event) => showError('Error: ' + (event.message || event.error)));
  window.addEventListener('unhandledrejection', (event) =>
    showError('Error: ' + (event.reason && event.reason.message ? event.reason.message : event.reason)));

  // ---- The state and the views -----------------------------------------------------------------

  const Grid = 64;          // heat-map raster per disk
  const LobeSteps = 360;    // directions of the lobe
  const SampleCount = 2000; // draws shown over the pdf
  const AlbedoThetas = Array.from({ length: 30 }, (_, i) => i * 3);
  const AlbedoStrata = 16;  // 16 x 16 stratified draws per angle

  const state = {
    catalog: [],
    entries: [],      // the material list: {label, kind: 'given' | 'model', ...}
    entry: null,
    material: null,   // the description being edited (as the user gave it)
    model: null,      // the last valid build: {handle, material (completed), flags}
    albedoKey: null,  // what the albedo curve was computed for
    albedo: null,
    tables: [],       // measured tables in the module's file system: {label, path}
    pending: false,
    buildMs: 0,       // the last build's time, counted in the next update's
    lastUpdateMs: NaN,
  };
  // What the views show, for tests and for the curious (window.scatterlabExplorer).
  const shown = { lobe: null, albedo: null, samples: null, updateMs: [] };

  function update() {
    state.pending = false;
    if (!state.model) return;
    const start = performance.now();
    const thetaI = Number($('theta-i').value), phiI = Number($('phi-i').value);
    $('theta-i-value').textContent = thetaI;
    $('phi-i-value').textContent = phiI;
    const wi = direction(thetaI, phiI);
    const model = state.model, transmission = model.flags.transmission;

    // Lobe: t over [-90, 90] (or [-180, 180] with transmission) in the plane of wi and the normal.
    const span = transmission ? 180 : 90;
    const t = [], lobePairs = new Float64Array(6 * (LobeSteps + 1));
    const phiOut = radians(phiI) + Math.PI;
    for (let i = 0; i <= LobeSteps; ++i) {
      const ti = -span + (2 * span * i) / LobeSteps;
      t.push(ti);
      const s = Math.sin(radians(ti));
      lobePairs.set([...wi, s * Math.cos(phiOut), s * Math.sin(phiOut), Math.cos(radians(ti))], 6 * i);
    }
    const lobe = { t, f: evalPairs(model, lobePairs, LobeSteps + 1) };
    const lobeMax = drawLobe($('lobe-canvas'), lobe, thetaI, transmission, $('lobe-cosine').checked);

    // Heat maps: f |cos| and the pdf on the same raster.
    const raster = diskPairs(Grid, wi, transmission);
    const values = evalPairs(model, raster.pairs, raster.count);
    const cosOut = (k) => Math.abs(raster.pairs[6 * k + 5]);
    let fMax = 0, pdfMax = 0;
    for (let k = 0; k < raster.count; ++k) {
      fMax = Math.max(fMax, mean3(values, 4 * k) * cosOut(k));
      pdfMax = Math.max(pdfMax, values[4 * k + 3]);
    }
    const log = $('log-scale').checked;
    const heat = drawDisks($('heatmap-canvas'), Grid, raster.disks, (k) => mean3(values, 4 * k) * cosOut(k), fMax, log, false);
    markDirection(heat, raster.disks, [-wi[0], -wi[1], wi[2]], '#ffffff', 'mirror');
    heat.fillStyle = '#1f2328';
    heat.fillText('max ' + format(fMax) + ' 1/sr', $('heatmap-canvas').width - 120, 12);

    // Samples over the pdf.
    const draws = drawSamples(model, wi, SampleCount, 1);
    const dots = drawDisks($('samples-canvas'), Grid, raster.disks, (k) => values[4 * k + 3], pdfMax, log, true);
    let delta = 0;
    for (let i = 0; i < SampleCount; ++i) {
      const v = draws.values.subarray(8 * i, 8 * i + 8);
      if (!(v[3] > 0)) continue;
      const disk = raster.disks.find((d) => d.below === v[2] < 0);
      if (!disk) continue;
      const [x, y] = diskPoint(v);
      const { x0, y0, size } = disk.frame;
      const isDelta = v[7] === 1;
      delta += isDelta ? 1 : 0;
      dots.fillStyle = isDelta ? '#cf222e' : 'rgba(188, 76, 0, 0.55)';
      dots.fillRect(x0 + ((x + 1) / 2) * size - (isDelta ? 3 : 1), y0 + ((1 - y) / 2) * size - (isDelta ? 3 : 1),
                    isDelta ? 6 : 2, isDelta ? 6 : 2);
    }
    $('samples-caption').textContent = SampleCount + ' draws of the model\'s own sampler (dots; ' + draws.failed +
      ' returned nothing, ' + delta + ' in delta lobes, red) over its pdf (grey, per solid angle, max ' +
      format(pdfMax) + ' 1/sr; equal-area projection, so the dots follow the grey).';

    // The albedo curve depends on the material and on phi only.
    const albedoKey = JSON.stringify(model.material) + '@' + phiI;
    const albedoComputed = state.albedoKey !== albedoKey;
    if (albedoComputed) {
      state.albedo = albedoCurve(model, AlbedoThetas, phiI, AlbedoStrata, 1);
      state.albedoKey = albedoKey;
    }
    drawAlbedo($('albedo-canvas'), AlbedoThetas, state.albedo, thetaI);
    $('albedo-caption').textContent = 'Directional albedo against θi at φi = ' + phiI + '° (r, g, b): the mean of ' +
      AlbedoStrata * AlbedoStrata + ' stratified draws of the sampler\'s weight per angle' +
      (transmission ? ', power through refractions' : '') + '.' +
      (state.albedo.invalid > 0 ? ' ' + state.albedo.invalid + ' draws with a negative or non-finite weight were left out.' : '');

    // The update's time: building the model after a change, and computing and drawing every view.
    const ms = performance.now() - start + state.buildMs;
    state.buildMs = 0;
    state.lastUpdateMs = ms;
    shown.lobe = { thetaI, phiI, t, f: Array.from(lobe.f), max: lobeMax };
    shown.albedo = { thetas: AlbedoThetas, values: Array.from(state.albedo.values) };
    shown.samples = { failed: draws.failed, delta };
    shown.updateMs.push(ms);
    $('timing').textContent = 'last update: ' + ms.toFixed(1) + ' ms (model, ' + (LobeSteps + 1) + ' lobe and ' +
      raster.count + ' map directions, ' + SampleCount + ' samples' +
      (albedoComputed ? ', ' + AlbedoThetas.length * AlbedoStrata * AlbedoStrata + ' albedo draws' : '') + ')';
  }

  function scheduleUpdate() {
    if (state.pending) return;
    state.pending = true;
    requestAnimationFrame(() => {
      try {
        update();
      } catch (error) {
        showError(error.message);
      }
    });
  }

  // Builds the edited description; on success the views follow it, otherwise the input that
  // changed shows the registry's message and the views keep the last valid material.
  function rebuild(changedInput, rerenderForm) {
    let model;
    const start = performance.now();
    try {
      model = build(state.material);
      state.buildMs = performance.now() - start;
    } catch (error) {
      const message = error.message.replace(/^scatterlab: /, '');
      if (changedInput) {
        changedInput.setCustomValidity(message);
        changedInput.classList.add('invalid');
        changedInput.title = message;
      }
      showError(message);
      return false;
    }
    document.querySelectorAll('.invalid').forEach((input) => {
      input.setCustomValidity('');
      input.classList.remove('invalid');
      input.title = '';
    });
    hideError();
    state.model = model;
    $('material-json').textContent = JSON.stringify(model.material, null, 2);
    if (rerenderForm) renderForm();
    scheduleUpdate();
    return true;
  }

  // ---- Inputs from the parameter specs ---------------------------------------------------------
  //
  // The inputs show the completed description (every default filled in) and edit the description
  // as given (state.material), so that defaults which depend on other keys (a subsurface
  // medium's eta) follow them. An input edits the value at its path, e.g. ['alpha'] or
  // ['materials', 1, 'alpha']; a nested object the given description lacks is first copied
  // from the completed one.

  const findModel = (type) => state.catalog.find((m) => m.type === type);
  const finite = (x) => typeof x === 'number' && Number.isFinite(x);
  const copy = (value) => JSON.parse(JSON.stringify(value));

  function givenObject(path) {
    let given = state.material, completed = state.model.material;
    for (const key of path) {
      if (given[key] === undefined) given[key] = copy(completed[key]);
      given = given[key];
      completed = completed[key];
    }
    return given;
  }
  function setGiven(path, value) {
    givenObject(path.slice(0, -1))[path[path.length - 1]] = value;
  }

  // A value for a parameter that has no default (an alternative's keys): the middle of a closed
  // range, otherwise 1 moved into the range.
  function initialValue(spec) {
    if (spec.kind === 'choice') return spec.choices[0];
    let x = 1;
    if (finite(spec.min) && finite(spec.max)) x = (spec.min + spec.max) / 2;
    else if (finite(spec.min) && x <= spec.min) x = spec.min + 1;
    else if (finite(spec.max) && x >= spec.max) x = spec.max - 1;
    return spec.kind === 'rgb' ? [x, x, x] : spec.kind === 'pair' ? [x, x] : x;
  }

  // A number input, with a slider when the range is finite (logarithmic when it spans more
  // than two decades from a positive minimum).
  function numberInput(spec, value, onValue, label) {
    const row = document.createElement('label');
    row.className = 'row';
    if (label) row.append(label + ' ');
    const box = document.createElement('input');
    box.type = 'number';
    box.step = 'any';
    box.value = value;
    box.dataset.parameter = spec.name;
    if (finite(spec.min)) box.min = spec.min;
    if (finite(spec.max)) box.max = spec.max;
    if (finite(spec.min) && finite(spec.max)) {
      const slider = document.createElement('input');
      slider.type = 'range';
      slider.min = 0;
      slider.max = 1000;
      slider.dataset.parameter = spec.name;
      const logarithmic = spec.min > 0 && spec.max / spec.min > 100;
      const toValue = (p) => (logarithmic ? spec.min * Math.pow(spec.max / spec.min, p / 1000)
                                          : spec.min + ((spec.max - spec.min) * p) / 1000);
      const toPosition = (x) => (logarithmic ? (1000 * Math.log(x / spec.min)) / Math.log(spec.max / spec.min)
                                             : (1000 * (x - spec.min)) / (spec.max - spec.min));
      slider.value = Math.round(toPosition(value));
      slider.addEventListener('input', () => {
        const x = Number(toValue(Number(slider.value)).toPrecision(4));
        box.value = x;
        onValue(x, slider);
      });
      box.addEventListener('change', () => {
        if (box.value !== '' && Number.isFinite(box.valueAsNumber)) slider.value = Math.round(toPosition(box.valueAsNumber));
      });
      row.append(slider);
    }
    // Text that is not a number goes to the registry as it is, which refuses it with the spec's message.
    box.addEventListener('input', () =>
      onValue(box.value !== '' && Number.isFinite(box.valueAsNumber) ? box.valueAsNumber : box.value, box));
    row.append(box);
    return row;
  }

  function labelledRow(text, input) {
    const row = document.createElement('label');
    row.className = 'row';
    row.append(text + ' ', input);
    return row;
  }

  function choiceSelect(name, choices, value, onChoice) {
    const select = document.createElement('select');
    select.dataset.parameter = name;
    for (const [label, choice] of choices) select.add(new Option(label, choice, false, choice === value));
    select.addEventListener('change', () => onChoice(select.value, select));
    return select;
  }

  function parameterInput(spec, completed, path) {
    const wrapper = document.createElement('div');
    wrapper.className = 'parameter';
    const title = document.createElement('div');
    const name = document.createElement('span'), allowed = document.createElement('span');
    name.className = 'name';
    name.textContent = spec.name;
    allowed.className = 'allowed';
    allowed.textContent = spec.allowed;
    title.append(name, ' ', allowed);
    title.title = spec.description;
    wrapper.append(title);
    const key = path.concat([spec.name]);
    const value = completed[spec.name];
    const set = (v, input, structural) => {
      setGiven(key, v);
      rebuild(input, structural);
    };
    if (spec.kind === 'number') {
      wrapper.append(numberInput(spec, value, (v, input) => set(v, input, false)));
    } else if (spec.kind === 'rgb' || spec.kind === 'pair') {
      const n = spec.kind === 'rgb' ? 3 : 2;
      const current = Array.isArray(value) ? value.slice() : Array(n).fill(value);
      const labels = spec.kind === 'rgb' ? ['r', 'g', 'b'] : ['x', 'y'];
      const components = document.createElement('div');
      components.className = 'components';
      current.forEach((x, c) => components.append(numberInput(spec, x, (v, input) => {
        current[c] = v;
        set(current.slice(), input, false);
      }, labels[c])));
      wrapper.append(components);
    } else if (spec.kind === 'choice') {
      wrapper.append(choiceSelect(spec.name, spec.choices.map((c) => [c, c]), value, (v, input) => set(v, input, true)));
    } else if (spec.kind === 'path') {
      const tables = state.tables.map((table) => [table.label, table.path]);
      if (!state.tables.some((table) => table.path === value)) tables.unshift([value || '(choose a table)', value || '']);
      wrapper.append(choiceSelect(spec.name, tables, value, (v, input) => set(v, input, true)));
      const note = document.createElement('div');
      note.className = 'allowed';
      note.textContent = 'tables: given with the page, or loaded with the file picker above';
      wrapper.append(note);
    } else if (spec.kind === 'materials') {
      value.forEach((nested, k) => wrapper.append(materialFieldset(nested, key.concat([k]), spec.name + '[' + k + ']')));
    }
    return wrapper;
  }

  // The inputs of one material (`completed`, at `path` in the description).
  function materialFieldset(completed, path, legend) {
    const fieldset = document.createElement('fieldset');
    const title = document.createElement('legend');
    title.textContent = legend;
    fieldset.append(title);
    const model = findModel(completed.type);
    if (!model) return fieldset;
    if (path.length > 0) {
      // A nested material's type (a blend's component): any BSDF model.
      const types = state.catalog.filter((m) => m.kind !== 'subsurface').map((m) => [m.type, m.type]);
      fieldset.append(labelledRow('type', choiceSelect('type', types, completed.type, (type, input) => {
        setGiven(path, { type });
        rebuild(input, true);
      })));
    }
    const about = document.createElement('p');
    about.className = 'small';
    about.textContent = model.description;
    fieldset.append(about);
    // Alternatives: sets of keys that say the same thing; the inputs of the one in use.
    const hidden = new Set();
    if (model.alternatives.length > 0) {
      const present = model.alternatives.findIndex((keys) => keys.every((key) => key in completed));
      const chosen = Math.max(present, 0);
      model.alternatives.forEach((keys, i) => { if (i !== chosen) keys.forEach((key) => hidden.add(key)); });
      const sets = model.alternatives.map((keys, i) => [keys.join(' + '), String(i)]);
      fieldset.append(labelledRow('given by', choiceSelect('alternatives', sets, String(chosen), (choice, input) => {
        const given = givenObject(path);
        model.alternatives.flat().forEach((key) => delete given[key]);
        if (Number(choice) !== 0)
          for (const key of model.alternatives[Number(choice)]) {
            const spec = model.parameters.find((p) => p.name === key);
            given[key] = spec.default !== null && spec.default !== undefined ? spec.default : initialValue(spec);
          }
        rebuild(input, true);
      })));
    }
    for (const spec of model.parameters)
      if (!hidden.has(spec.name) && spec.name in completed) fieldset.append(parameterInput(spec, completed, path));
    return fieldset;
  }

  function renderForm() {
    const container = $('parameters');
    container.textContent = '';
    container.append(materialFieldset(state.model.material, [], 'parameters'));
  }

  // ---- The material list, tables and preloaded materials ---------------------------------------

  function loadTableScript(table) {
    if (window.scatterlabTables && window.scatterlabTables[table.path]) return Promise.resolve();
    return new Promise((resolve, reject) => {
      const script = document.createElement('script');
      script.src = table.script;
      script.onload = () => resolve();
      script.onerror = () => reject(new Error('the table ' + table.script + ' could not be loaded (is it beside index.html?)'));
      document.head.append(script);
    });
  }
  function decodeBase64(text) {
    const binary = atob(text);
    const bytes = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
    return bytes;
  }
  async function installTables(tables) {
    for (const table of tables) {
      if (state.tables.some((known) => known.path === table.path)) continue;
      await loadTableScript(table);
      const data = window.scatterlabTables && window.scatterlabTables[table.path];
      if (typeof data !== 'string') throw new Error('the table ' + table.script + ' holds no data for ' + table.path);
      fileSystem().mkdirTree(table.path.replace(/\/[^/]*$/, ''));
      fileSystem().writeFile(table.path, decodeBase64(data));
      delete window.scatterlabTables[table.path];
      state.tables.push({ label: table.label || table.path, path: table.path });
    }
  }

  async function selectEntry(index) {
    const entry = state.entries[index];
    if (!entry) return;
    $('material-select').value = String(index);
    state.entry = entry;
    if (entry.kind === 'given') {
      $('timing').textContent = 'loading ' + entry.name + '…';
      try {
        await installTables(entry.tables || []);
      } catch (error) {
        showError(error.message);
        return;
      }
      state.material = copy(entry.material);
    } else if (entry.type === 'measured') {
      const table = state.tables[state.tables.length - 1];
      if (!table) {
        showError('A measured material needs a table: load a MERL .binary file with the file picker above.');
        return;
      }
      state.material = { type: 'measured', file: table.path };
    } else {
      state.material = { type: entry.type };
    }
    state.albedoKey = null;
    rebuild($('material-select'), true);
  }

  function fillMaterialList() {
    const select = $('material-select');
    select.textContent = '';
    state.entries.forEach((entry, i) => select.add(new Option(entry.label, String(i))));
  }

  async function pickTable(file) {
    const bytes = new Uint8Array(await file.arrayBuffer());
    const path = api.loadTable('picked-' + (state.tables.length + 1) + '-' + file.name, bytes);
    const material = { type: 'measured', file: path };
    let model;
    try {
      model = build(material);
    } catch (error) {
      // An unreadable table: its message, and the views keep what they showed.
      fileSystem().unlink(path);
      showError('"' + file.name + '": ' + error.message.replace(/^scatterlab: /, ''));
      return;
    }
    state.tables.push({ label: file.name, path });
    state.entries.push({ kind: 'given', label: 'table: ' + file.name, name: file.name, material, tables: [] });
    fillMaterialList();
    await selectEntry(state.entries.length - 1);
    return model;
  }

  async function start() {
    await api.ready;
    state.catalog = api.models();
    const preload = (window.scatterlabPreload && window.scatterlabPreload.materials) || [];
    for (const given of preload)
      state.entries.push({ kind: 'given', label: 'given: ' + given.name, id: given.id, name: given.name,
                           material: given.material, tables: given.tables });
    for (const model of state.catalog)
      state.entries.push({ kind: 'model', label: 'model: ' + model.type, type: model.type });
    fillMaterialList();
    $('material-select').addEventListener('change', () => selectEntry(Number($('material-select').value)));
    $('table-file').addEventListener('change', () => {
      const file = $('table-file').files[0];
      if (file) pickTable(file).catch((error) => showError(error.message));
    });
    for (const id of ['theta-i', 'phi-i', 'lobe-cosine', 'log-scale'])
      $(id).addEventListener('input', scheduleUpdate);
    window.addEventListener('hashchange', () => selectFromHash());
    if (!(await selectFromHash())) {
      const first = state.entries.findIndex((e) => e.kind === 'given' || e.type === 'conductor');
      await selectEntry(Math.max(first, 0));
    }
    return api;
  }

  // "#ID" selects the given material with that id (the lab report's links).
  async function selectFromHash() {
    const id = decodeURIComponent(location.hash.replace(/^#/, ''));
    const index = state.entries.findIndex((e) => e.kind === 'given' && e.id === id);
    if (!id || index < 0) return false;
    await selectEntry(index);
    return true;
  }

  window.scatterlabExplorer = { state, shown, selectEntry, update };
  window.scatterlabExplorer.ready = start().catch((error) => showError(error.message));
})();
