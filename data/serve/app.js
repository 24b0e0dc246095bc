// ris serve: the page's behaviour (docs/serve.md). Talks to the JSON API only.
//
// Changes are sent as the radar file's own keys (`{"radar": {"film": {"gamma":
// 0.8}}}`), so the server checks them like a file and its messages name the
// key. Latest request wins: a new change aborts the request in flight, the
// server drops one overtaken while waiting (HTTP 409), and changes not yet
// accepted stay pending and go with the next request, so none is lost.
'use strict';

const $ = (id) => document.getElementById(id);
let state = null;        // GET /api/state
let run = null;          // the current run's summary
let pending = {};        // changes not yet accepted: {"radar.film.gamma": 0.8, "seed": 3}
let inFlight = null;     // AbortController of the simulate request in flight
let selectedObject = -1;

// ---- API ----
async function api(path, options = {}) {
  const res = await fetch(path, options);
  const type = res.headers.get('Content-Type') || '';
  const body = type.startsWith('application/json') ? await res.json() : await res.text();
  if (!res.ok && res.status !== 409) throw new Error(body.error || res.statusText);
  return { status: res.status, body };
}
// Every request that changes something says JSON: the server refuses any
// other type there (a cross-site page cannot send it without a preflight the
// server never approves: docs/serve.md, "Threat model").
const sendJson = (method, path, obj, signal) => api(path, {
  method, headers: { 'Content-Type': 'application/json' },
  body: JSON.stringify(obj), signal });
const postJson = (path, obj, signal) => sendJson('POST', path, obj, signal);

function showError(message) { $('error').textContent = message || ''; }
function setStatus(text) { $('status').textContent = text; }

// ---- the request body from pending changes ----
// "radar.film.gamma" -> {radar: {film: {gamma: v}}}
function bodyFromPending(changes) {
  const body = {};
  for (const [path, value] of Object.entries(changes)) {
    const keys = path.split('.');
    let node = body;
    for (const k of keys.slice(0, -1)) node = (node[k] = node[k] || {});
    node[keys[keys.length - 1]] = value;
  }
  return body;
}

function controlValue(el) {
  if (el.type === 'checkbox') return el.checked;
  if (el.dataset.unit) return `${el.value} ${el.dataset.unit}`;
  if (el.type === 'number' || el.type === 'range') return Number(el.value);
  return el.value;
}

function controlKey(el) {
  return el.dataset.radar ? 'radar.' + el.dataset.radar : el.dataset.top;
}

async function simulate() {
  if (inFlight) inFlight.abort();
  const controller = new AbortController();
  inFlight = controller;
  const sent = { ...pending };
  setStatus('simulating…');
  try {
    const { status, body } = await postJson('/api/simulate', bodyFromPending(sent),
                                            controller.signal);
    if (status === 409) return;  // overtaken: the newer request carries these changes
    for (const [k, v] of Object.entries(sent)) if (pending[k] === v) delete pending[k];
    showError('');
    await showRun(body);
  } catch (e) {
    if (e.name === 'AbortError') return;
    // Refused: forget the changes (the server kept its state) and show why.
    for (const k of Object.keys(sent)) delete pending[k];
    showError(e.message);
    setStatus('refused');
  } finally {
    if (inFlight === controller) inFlight = null;
  }
}

function onControl(ev) {
  const el = ev.target;
  const key = controlKey(el);
  if (!key) return;
  pending[key] = controlValue(el);
  updateOutputs();
  simulate();
}

// ---- showing a run ----
function currentView() { return $('presentation').value; }

function overlayMasks() {
  return [...document.querySelectorAll('.overlay:checked')].map((c) => c.value).join(',');
}

function loadImage(img, url) {
  // The same picture (the scene between edits): nothing to fetch.
  if (img.complete && img.naturalWidth && img.src === new URL(url, location.href).href) {
    return Promise.resolve(true);
  }
  return new Promise((resolve) => {
    img.onload = () => resolve(true);
    img.onerror = () => resolve(false);
    img.src = url;
  });
}

async function showImages() {
  if (!run) return;
  let view = currentView();
  if (!run.images[view]) view = 'slant';
  $('image-title').textContent = `Image (${view}, run ${run.id}, ${run.kind})`;
  const masks = overlayMasks();
  const overlayView = view === 'ground' ? '' : view;
  const overlayImg = $('image-overlay');
  const sceneOverlay = $('scene-overlay');
  const withOverlays = masks && run.kind !== 'ppi';
  const loads = [loadImage($('image'), run.images[view])];
  if (withOverlays && overlayView) {
    loads.push(loadImage(overlayImg, `/api/overlay/${overlayView}.png?masks=${masks}&run=${run.id}`));
    overlayImg.hidden = false;
  } else {
    overlayImg.hidden = true;
  }
  loads.push(loadImage($('scene'), run.images.scene));
  if (withOverlays) {
    loads.push(loadImage(sceneOverlay, `/api/overlay/scene.png?masks=${masks}&run=${run.id}`));
    sceneOverlay.hidden = false;
  } else {
    sceneOverlay.hidden = true;
  }
  await Promise.all(loads);
  $('image').dataset.run = run.id;
  $('image').dataset.view = view;
}

async function showRun(summary) {
  run = summary;
  const extra = summary.film_only ? ' (film only)' : '';
  setStatus(`run ${run.id}: ${(1000 * run.seconds).toFixed(0)} ms${extra}` +
            (run.shadow_percent !== undefined
              ? `; shadow ${run.shadow_percent.toFixed(1)}%, layover ${run.layover_percent.toFixed(1)}%`
              : ''));
  await showImages();
  drawHistogram();
  if (run.kind !== 'ppi') {
    api('/api/shadowmap.txt').then(({ body }) => { $('shadow-map').textContent = body; })
      .catch(() => {});
  } else {
    $('shadow-map').textContent = '(no shadow map for a PPI)';
  }
  if (!summary.film_only) drawSigma0();
}

// ---- charts ----
const palette = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b', '#e377c2',
                 '#7f7f7f', '#bcbd22', '#17becf'];

async function drawSigma0() {
  const { body } = await api('/api/sigma0');
  const c = $('sigma0-chart');
  const g = c.getContext('2d');
  g.clearRect(0, 0, c.width, c.height);
  const values = body.curves.flatMap((cv) => cv.sigma0_db.filter((v) => v !== null));
  if (!values.length) return;
  const lo = Math.floor(Math.max(Math.min(...values), -50) / 5) * 5;
  const hi = Math.ceil(Math.max(...values) / 5) * 5;
  const left = 34, bottom = c.height - 18, w = c.width - left - 100, h = bottom - 8;
  const X = (deg) => left + (deg / 90) * w;
  const Y = (db) => bottom - ((Math.max(db, lo) - lo) / (hi - lo || 1)) * h;
  g.strokeStyle = '#ccc'; g.fillStyle = '#555'; g.font = '10px sans-serif';
  for (let db = lo; db <= hi; db += 5) {
    g.beginPath(); g.moveTo(left, Y(db)); g.lineTo(left + w, Y(db)); g.stroke();
    g.fillText(String(db), 2, Y(db) + 3);
  }
  for (let deg = 0; deg <= 90; deg += 15) g.fillText(String(deg), X(deg) - 5, bottom + 12);
  body.curves.forEach((cv, i) => {
    g.strokeStyle = palette[i % palette.length];
    g.beginPath();
    let started = false;
    cv.sigma0_db.forEach((v, k) => {
      if (v === null) { started = false; return; }
      const x = X(body.angles_deg[k]), y = Y(v);
      if (started) g.lineTo(x, y); else g.moveTo(x, y);
      started = true;
    });
    g.stroke();
    g.fillStyle = g.strokeStyle;
    g.fillText(cv.name.slice(0, 16), left + w + 6, 12 + 11 * i);
  });
  g.fillStyle = '#555';
  g.fillText(`dB vs local incidence, deg; ${(body.frequency_hz / 1e9).toFixed(2)} GHz`, left, 8);
}

async function drawHistogram() {
  const { body } = await api('/api/histogram');
  const c = $('histogram');
  const g = c.getContext('2d');
  g.clearRect(0, 0, c.width, c.height);
  // Scaled to the tallest bar between the ends: shadow (0) and saturation
  // (255) spikes would flatten the rest; they are drawn clipped.
  const max = Math.max(1, ...body.counts.slice(1, 255));
  const w = c.width / 256;
  g.fillStyle = '#3d4a63';
  body.counts.forEach((n, k) => {
    const h = Math.min(1, n / max) * (c.height - 4);
    g.fillRect(k * w, c.height - h, Math.max(w, 1), h);
  });
}

// ---- zoom, pan and click on a viewport ----
// paint (optional): {active(), down(x, y), move(x, y), up()} in image pixels;
// while active, dragging paints instead of panning.
function makeZoomable(viewport, stage, img, onClick, paint) {
  const t = { scale: 1, x: 0, y: 0 };
  const apply = () => {
    stage.style.transform = `translate(${t.x}px, ${t.y}px) scale(${t.scale})`;
  };
  const fit = () => {
    if (!img.naturalWidth) return;
    t.scale = Math.min(viewport.clientWidth / img.naturalWidth,
                       viewport.clientHeight / img.naturalHeight);
    t.x = 0; t.y = 0;
    apply();
  };
  // Fit the first picture, and again when the size changes (another
  // presentation); keep the user's zoom across runs of the same size.
  let fittedSize = '';
  img.addEventListener('load', () => {
    const size = `${img.naturalWidth}x${img.naturalHeight}`;
    if (size !== fittedSize) { fittedSize = size; fit(); }
  });
  viewport.addEventListener('dblclick', fit);
  viewport.addEventListener('wheel', (ev) => {
    ev.preventDefault();
    const r = viewport.getBoundingClientRect();
    const px = ev.clientX - r.left, py = ev.clientY - r.top;
    const k = ev.deltaY < 0 ? 1.25 : 0.8;
    t.x = px - (px - t.x) * k; t.y = py - (py - t.y) * k; t.scale *= k;
    apply();
  }, { passive: false });
  const pixelAt = (ev) => {
    const r = img.getBoundingClientRect();
    return [((ev.clientX - r.left) / r.width) * img.naturalWidth,
            ((ev.clientY - r.top) / r.height) * img.naturalHeight];
  };
  let drag = null;
  let painting = false;
  viewport.addEventListener('mousedown', (ev) => {
    if (paint && paint.active()) {
      painting = true;
      paint.down(...pixelAt(ev));
      return;
    }
    drag = { x0: ev.clientX, y0: ev.clientY, tx: t.x, ty: t.y, moved: false };
  });
  window.addEventListener('mousemove', (ev) => {
    if (painting) { paint.move(...pixelAt(ev)); return; }
    if (!drag) return;
    const dx = ev.clientX - drag.x0, dy = ev.clientY - drag.y0;
    if (Math.abs(dx) + Math.abs(dy) > 3) drag.moved = true;
    if (drag.moved) { t.x = drag.tx + dx; t.y = drag.ty + dy; apply(); }
  });
  window.addEventListener('mouseup', (ev) => {
    if (painting) { painting = false; paint.up(); return; }
    if (drag && !drag.moved && viewport.contains(ev.target)) {
      const r = img.getBoundingClientRect();
      const x = Math.floor(((ev.clientX - r.left) / r.width) * img.naturalWidth);
      const y = Math.floor(((ev.clientY - r.top) / r.height) * img.naturalHeight);
      if (x >= 0 && y >= 0 && x < img.naturalWidth && y < img.naturalHeight) onClick(x, y);
    }
    drag = null;
  });
}

// ---- the pixel inspector ----
const inspectorRows = [
  ['view', 'view'], ['row', 'row'], ['col', 'col'], ['line', 'line'], ['bin', 'bin'],
  ['ground_range_m', 'ground range, m'],
  ['elevation_m', 'elevation, m'], ['category_name', 'category'],
  ['local_incidence_deg', 'local incidence, deg'], ['sigma0_db', 'sigma0, dB'],
  ['slant_range_m', 'slant range, m'], ['incidence_deg', 'incidence, deg'],
  ['incidence_flat_deg', 'incidence (flat), deg'], ['looks', 'N (looks)'],
  ['mean_power_dbw', 'mean power, dBW'], ['speckled_power_w', 'speckled power, W'],
  ['greytone', 'greytone'], ['flags', 'flags'],
];

function fmtValue(v) {
  if (v === null || v === undefined) return '—';
  if (Array.isArray(v)) return v.length ? v.join(', ') : 'none';
  if (typeof v === 'number') return Number.isInteger(v) ? String(v) : v.toPrecision(6);
  return String(v);
}

async function inspect(view, x, y) {
  try {
    const { body } = await api(`/api/inspect?view=${view}&x=${x}&y=${y}`);
    const rows = [];
    const add = (obj, prefix) => {
      for (const [key, label] of inspectorRows) {
        if (key in obj) rows.push(`<tr><td>${prefix}${label}</td><td data-key="${key}">` +
                                  `${fmtValue(obj[key])}</td></tr>`);
      }
    };
    add(body, '');
    if (body.pixel) add(body.pixel, 'pixel ');
    $('inspector').innerHTML = rows.join('');
    showError('');
  } catch (e) {
    showError(e.message);
  }
}

// ---- scene editing ----
function objects() {
  const d = state && state.scene.description;
  return (d && d.object) || [];
}

function listObjects() {
  const list = $('object-list');
  list.innerHTML = '';
  objects().forEach((o, i) => {
    const opt = document.createElement('option');
    opt.value = i;
    opt.textContent = `${i}: ${o.type}${o.category !== undefined ? ' cat ' + o.category : ''}`;
    list.appendChild(opt);
  });
  if (selectedObject >= objects().length) selectedObject = objects().length - 1;
  list.value = selectedObject >= 0 ? String(selectedObject) : '';
  showObjectFields();
}

function showObjectFields() {
  const box = $('object-fields');
  box.innerHTML = '';
  const o = objects()[selectedObject];
  if (!o) return;
  for (const [k, v] of Object.entries(o)) {
    if (k === 'type') continue;
    const label = document.createElement('label');
    label.innerHTML = `<span>${k}</span>`;
    const input = document.createElement('input');
    input.dataset.key = k;
    input.value = typeof v === 'object' ? JSON.stringify(v) : String(v);
    label.appendChild(input);
    box.appendChild(label);
  }
}

// A field's text as the JSON value the scene parser expects: numbers and
// JSON arrays as such, quantities with units ("300 ft") as strings.
function parseField(text) {
  const t = text.trim();
  if (t === 'true' || t === 'false') return t === 'true';
  if (t !== '' && !isNaN(Number(t))) return Number(t);
  if (t.startsWith('[')) { try { return JSON.parse(t); } catch (e) { /* as text */ } }
  return t;
}

async function editScene(request) {
  try {
    setStatus('editing…');
    const { body } = await request();
    if (body.objects) {
      state.scene.description = state.scene.description || {};
      state.scene.description.object = body.objects;
      listObjects();
    }
    showError('');
    await showRun(body.run);
  } catch (e) {
    showError(e.message);
    setStatus('edit refused');
  }
}

function sceneCentre() {
  const s = state.scene;
  return { x: 0.5 * s.cols * s.cell_m, y: 0.5 * s.rows * s.cell_m };
}

function addObject(object) {
  editScene(async () => {
    const r = await postJson('/api/scene/objects', object);
    selectedObject = r.body.objects.length - 1;
    return r;
  });
}

function onSceneClick(x, y) {
  if ($('move-mode').checked && selectedObject >= 0 && state.scene.editable) {
    const s = state.scene;
    // Objects are placed from the grid's south-west corner (x east, y north).
    const xm = (x + 0.5) * s.cell_m;
    const ym = (s.rows - y - 0.5) * s.cell_m;
    editScene(() => postJson(`/api/scene/objects/${selectedObject}`,
                             { x: Math.round(xm), y: Math.round(ym) }));
    return;
  }
  inspect(run && run.images.geocoded ? 'scene' : 'scene', x, y);
}

function wireSceneTools() {
  $('object-list').addEventListener('change', (ev) => {
    selectedObject = Number(ev.target.value);
    showObjectFields();
  });
  $('add-box').addEventListener('click', () => {
    const c = sceneCentre();
    addObject({ type: 'box', x: Math.round(c.x), y: Math.round(c.y), length: 300, width: 300,
                height: 150, rotation: 0, category: 5 });
  });
  $('add-pyramid').addEventListener('click', () => {
    const c = sceneCentre();
    addObject({ type: 'pyramid', x: Math.round(c.x), y: Math.round(c.y), base: 400, height: 200,
                rotation: 0, category: 4 });
  });
  $('delete-object').addEventListener('click', () => {
    if (selectedObject < 0) return;
    editScene(() => sendJson('DELETE', `/api/scene/objects/${selectedObject}`, {}));
  });
  $('undo').addEventListener('click', () => editScene(() => postJson('/api/scene/undo', {})));
  $('apply-object').addEventListener('click', () => {
    if (selectedObject < 0) return;
    const changes = {};
    for (const input of $('object-fields').querySelectorAll('input')) {
      changes[input.dataset.key] = parseField(input.value);
    }
    editScene(() => postJson(`/api/scene/objects/${selectedObject}`, changes));
  });
  const save = (what) => async () => {
    try {
      const { body } = await postJson(`/api/${what}/save`, { name: $('save-name').value });
      $('saved').textContent = `saved ${body.file} in the output folder (--out)`;
      showError('');
    } catch (e) {
      showError(e.message);
    }
  };
  $('save-scene').addEventListener('click', save('scene'));
  $('save-radar').addEventListener('click', save('radar'));
  $('write-products').addEventListener('click', async () => {
    try {
      const { body } = await postJson('/api/products', {});
      $('saved').textContent = `products in ${body.folder} in the output folder (--out)`;
      $('products').innerHTML = '<li><a href="/api/products.zip" download>all, as a zip</a></li>' +
        body.files
          .map((f) => `<li><a href="/api/products/${encodeURIComponent(f)}" download>${f}</a></li>`)
          .join('');
    } catch (e) {
      showError(e.message);
    }
  });
}

// ---- painting categories (raster scenes) ----
let stroke = [];   // brush centres, [col, row]
let polygon = [];  // polygon vertices, [col, row]
const paintMode = () => document.querySelector('input[name=paint-mode]:checked').value;

async function sendPaint(shape) {
  const body = { category: Number($('paint-category').value), ...shape };
  await editScene(() => postJson('/api/scene/paint', body));
}

const scenePaint = {
  active: () => !state.scene.editable && paintMode() !== 'off',
  down(x, y) {
    if (paintMode() === 'polygon') {
      polygon.push([x, y]);
      $('polygon-note').textContent = `${polygon.length} vertices`;
    } else {
      stroke = [[x, y]];
    }
  },
  move(x, y) {
    if (paintMode() !== 'brush' || !stroke.length) return;
    // A centre every half radius along the path keeps the stroke continuous
    // however far the mouse jumped between two events.
    const step = 0.5 * Number($('paint-radius').value);
    const [px, py] = stroke[stroke.length - 1];
    const n = Math.floor(Math.hypot(x - px, y - py) / step);
    for (let k = 1; k <= n; ++k) stroke.push([px + ((x - px) * k) / n, py + ((y - py) * k) / n]);
  },
  up() {
    if (paintMode() !== 'brush' || !stroke.length) return;
    const brush = stroke;
    stroke = [];
    sendPaint({ brush, radius: Number($('paint-radius').value) });
  },
};

function wirePaintTools() {
  $('fill-polygon').addEventListener('click', () => {
    const vertices = polygon;
    polygon = [];
    $('polygon-note').textContent = '';
    sendPaint({ polygon: vertices });
  });
  $('clear-polygon').addEventListener('click', () => {
    polygon = [];
    $('polygon-note').textContent = '';
  });
  $('paint-undo').addEventListener('click', () => editScene(() => postJson('/api/scene/undo', {})));
}

// ---- controls from the state ----
function updateOutputs() {
  $('depression-value').textContent = $('depression').value;
  $('density-value').textContent = $('density-range').value;
  $('gamma-value').textContent = $('gamma').value;
}

function fillSelect(select, names, value) {
  select.innerHTML = names.map((n) => `<option>${n}</option>`).join('');
  select.value = value;
}

function setControls() {
  const p = state.radar.params;
  const deg = 180 / Math.PI;
  $('mode').value = p.mode;
  $('frequency').value = (p.frequency_hz / 1e9).toFixed(3);
  $('polarisation').value = p.polarisation;
  const track = p.track || {};
  const altitude = track.altitude_m || p.altitude_m || 0;
  $('altitude').value = Math.round(altitude);
  if (altitude > 0 && p.near_slant_range_m > altitude) {
    $('depression').value = (Math.asin(altitude / p.near_slant_range_m) * deg).toFixed(1);
  }
  $('swath').value = Math.round(p.far_slant_range_m - p.near_slant_range_m);
  $('heading').value = ((track.heading_rad || 0) * deg).toFixed(1);
  $('look-side').value = track.look_side || 'right';
  $('beamwidth').value = (p.azimuth_beamwidth_rad * 1e3).toFixed(3);
  $('pulse-width').value = (p.pulse_width_s * 1e9).toFixed(1);
  $('density-range').value = p.film.density_range;
  $('gamma').value = p.film.gamma;
  $('fading').checked = p.film.terms.fading;
  $('seed').value = state.seed;
  fillSelect($('radar-preset'), state.radar_presets, '');
  fillSelect($('backscatter'), state.backscatter_libraries, state.backscatter);
  $('scene-tools').hidden = !state.scene.editable;
  $('paint-tools').hidden = state.scene.editable;
  $('paint-category').innerHTML = state.categories
    .map((c) => `<option value="${c.id}">${c.id}: ${c.name}</option>`).join('');
  updateOutputs();
}

async function loadState() {
  const { body } = await api('/api/state');
  state = body;
  setControls();
  listObjects();
}

async function main() {
  makeZoomable($('image-viewport'), $('image-stage'), $('image'),
               (x, y) => inspect($('image').dataset.view || 'slant', x, y));
  makeZoomable($('scene-viewport'), $('scene-stage'), $('scene'), onSceneClick, scenePaint);
  for (const el of document.querySelectorAll('[data-radar], [data-top]')) {
    el.addEventListener(el.type === 'range' ? 'input' : 'change', onControl);
  }
  $('radar-preset').addEventListener('change', async (ev) => {
    pending = {};
    try {
      const { body } = await postJson('/api/simulate', { radar_preset: ev.target.value });
      await loadState();
      await showRun(body);
    } catch (e) {
      showError(e.message);
    }
  });
  $('presentation').addEventListener('change', showImages);
  for (const c of document.querySelectorAll('.overlay')) c.addEventListener('change', showImages);
  wireSceneTools();
  wirePaintTools();
  try {
    await loadState();
    await showRun(state.run);
  } catch (e) {
    showError(e.message);
  }
}

main();
