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
let sceneView = null;    // the scene viewport's zoom (linked to the map and the slant view)
let imageView = null;    // the image viewport's zoom (the slant view linked to the scene)
let compare = null;      // GET /api/compare: the comparison shown, or null

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

// Debian's Leaflet and Chart.js, when ris serve found them (docs/serve.md).
const hasLeaflet = () => typeof window.L !== 'undefined' && !!window.L.map;
const hasChart = () => typeof window.Chart !== 'undefined';

function setOverlay(img, url) {
  // Off means no picture at all: no stale mask of an earlier run or
  // presentation can stay on screen.
  if (!url) {
    img.hidden = true;
    img.removeAttribute('src');
    return Promise.resolve(true);
  }
  img.hidden = false;
  return loadImage(img, url);
}

async function showImages() {
  if (!run) return;
  let view = currentView();
  if (!run.images[view]) view = 'slant';
  $('image-title').textContent = `Image (${view}, run ${run.id}, ${run.kind})`;
  const masks = overlayMasks();
  // Masks exist on the slant grid and the scene grid (geocoded is on the
  // scene grid); the ground-range image and a PPI's scope have none.
  const overlayView = run.kind === 'ppi' || view === 'ground' ? '' : view;
  const withOverlays = masks && run.kind !== 'ppi';
  const mapView = view === 'geocoded' && hasLeaflet();
  $('image-viewport').hidden = mapView;
  $('map').hidden = !mapView;
  const loads = [];
  if (mapView) {
    loads.push(showMap(masks));
    await setOverlay($('image-overlay'), '');
  } else {
    // Leaving the map: its masks go too (none waits there for a later run).
    for (const [name, layer] of Object.entries(mapLayers.masks)) {
      layer.remove();
      delete mapLayers.masks[name];
    }
    loads.push(loadImage($('image'), run.images[view]));
    loads.push(setOverlay($('image-overlay'), withOverlays && overlayView
      ? `/api/overlay/${overlayView}.png?masks=${masks}&run=${run.id}` : ''));
  }
  loads.push(loadImage($('scene'), run.images.scene));
  loads.push(setOverlay($('scene-overlay'), withOverlays
    ? `/api/overlay/scene.png?masks=${masks}&run=${run.id}` : ''));
  await Promise.all(loads);
  $('image').dataset.run = run.id;
  $('image').dataset.view = view;
  if (view !== $('image-cursor').dataset.view) $('image-cursor').hidden = true;
  applyAspect(view);
  showOrientation(view);
  applyOpacity();
  updateScaleBars();
}

// ---- the map (Leaflet, simple CRS in the scene's metres, north up) ----
let map = null;
const mapLayers = { base: null, scene: null, masks: {}, marker: null };

function sceneBounds() {
  const s = state.scene;
  return [[0, 0], [s.rows * s.cell_m, s.cols * s.cell_m]];  // [y north, x east]
}

function ensureMap() {
  if (map) return map;
  map = L.map('map', { crs: L.CRS.Simple, minZoom: -6, maxZoom: 6, zoomSnap: 0.25,
                       attributionControl: false });
  // In a simple CRS distances are in map units, here metres: a true scale bar.
  L.control.scale({ imperial: false, metric: true, maxWidth: 160 }).addTo(map);
  const north = L.control({ position: 'topright' });
  north.onAdd = () => {
    const d = L.DomUtil.create('div', 'north leaflet-north');
    d.innerHTML = 'N<br>&#x2191;';
    d.style.position = 'static';
    return d;
  };
  north.addTo(map);
  map.on('click', (ev) => {
    const s = state.scene;
    const col = Math.floor(ev.latlng.lng / s.cell_m);
    const row = Math.floor(s.rows - ev.latlng.lat / s.cell_m);
    if (col >= 0 && row >= 0 && col < s.cols && row < s.rows) inspect('geocoded', col, row);
  });
  map.fitBounds(sceneBounds());
  // Linked zoom: the scene view shows what the map shows (same grid).
  map.on('moveend zoomend', () => {
    if (!$('link-zoom').checked || $('map').hidden || !sceneView) return;
    const b = map.getBounds();
    const s = state.scene;
    sceneView.showRegion(b.getWest() / s.cell_m, s.rows - b.getNorth() / s.cell_m,
                         b.getEast() / s.cell_m, s.rows - b.getSouth() / s.cell_m);
  });
  return map;
}

function mapImage(layer, url, opacity) {
  if (layer) { layer.setUrl(url); layer.setOpacity(opacity); return layer; }
  return L.imageOverlay(url, sceneBounds(), { opacity }).addTo(map);
}

async function showMap(masks) {
  ensureMap();
  map.invalidateSize();
  const bounds = sceneBounds();
  mapLayers.base = mapImage(mapLayers.base, run.images.geocoded, 1);
  mapLayers.base.setBounds(L.latLngBounds(bounds));
  const el = mapLayers.base.getElement();
  if (el) { el.id = 'map-image'; el.style.filter = 'url(#stretch)'; el.dataset.run = run.id; }
  // One layer per mask, so each toggles on its own.
  const wanted = masks ? masks.split(',') : [];
  for (const name of ['shadow', 'layover', 'backfacing']) {
    const layer = mapLayers.masks[name];
    if (wanted.includes(name)) {
      mapLayers.masks[name] = mapImage(layer,
        `/api/overlay/geocoded.png?masks=${name}&run=${run.id}`, overlayOpacity());
      mapLayers.masks[name].setBounds(L.latLngBounds(bounds));
    } else if (layer) {
      layer.remove();
      delete mapLayers.masks[name];
    }
  }
}

function overlayOpacity() { return Number($('overlay-opacity').value); }

function applyOpacity() {
  const o = overlayOpacity();
  for (const id of ['image-overlay', 'scene-overlay']) $(id).style.opacity = o;
  for (const layer of Object.values(mapLayers.masks)) layer.setOpacity(o);
}

// The slant image in its true aspect: a bin is range_bin_m of slant range
// across, a line line_spacing_m of track down (4:1 for the seed's radar).
function applyAspect(view) {
  const img = $('image');
  const m = run.map || {};
  img.style.width = '';
  img.style.height = '';
  if (view !== 'slant' || !m.range_bin_m || !m.line_spacing_m || !img.naturalWidth) return;
  const unit = Math.min(m.range_bin_m, m.line_spacing_m);
  img.style.width = `${img.naturalWidth * m.range_bin_m / unit}px`;
  img.style.height = `${img.naturalHeight * m.line_spacing_m / unit}px`;
  img.dispatchEvent(new Event('resized'));
}

function showOrientation(view) {
  const box = $('image-orientation');
  const m = run.map || {};
  box.hidden = false;
  if (run.kind === 'ppi') {
    box.textContent = view === 'slant' ? 'PPI scope: north up' : 'B-scope: range across';
    return;
  }
  if (view === 'geocoded') { box.hidden = true; return; }
  // Lines are in flight order (first at the top), bins near range first.
  const h = (m.heading_deg || 0).toFixed(0);
  box.textContent = `\u2193 flight, heading ${h}\u00b0 (top: track start)\n` +
    `\u2192 ${view === 'slant' ? 'slant' : 'ground'} range, looking ${m.look_side || 'right'}` +
    (view === 'slant' && $('link-zoom').checked ? '\nzoom linked to the scene (line, range mapping)' : '');
  box.dataset.heading = h;
}

// ---- scale bars ----
function niceLength(m) {
  const p = Math.pow(10, Math.floor(Math.log10(m)));
  for (const k of [5, 2, 1]) if (k * p <= m) return k * p;
  return p;
}

function fmtLength(m) { return m >= 1000 ? `${m / 1000} km` : `${m} m`; }

// A bar of a round length near 100 screen pixels; data-metres and
// data-px say what it shows (the browser test checks them against the
// cell size).
function drawScaleBar(bar, img, metresPerPixel) {
  const r = img.getBoundingClientRect();
  if (!img.naturalWidth || !r.width || !metresPerPixel) { bar.hidden = true; return; }
  const pxPerMetre = r.width / img.naturalWidth / metresPerPixel;
  const metres = niceLength(100 / pxPerMetre);
  const px = metres * pxPerMetre;
  bar.hidden = false;
  bar.querySelector('.bar').style.width = `${px}px`;
  bar.querySelector('span').textContent = fmtLength(metres);
  bar.dataset.metres = metres;
  bar.dataset.px = px.toFixed(2);
}

function updateScaleBars() {
  if (!run || !state) return;
  drawScaleBar($('scene-scalebar'), $('scene'), state.scene.cell_m);
  const view = $('image').dataset.view;
  const m = run.map || {};
  // Slant: metres of slant range across; geocoded (plain image): cells.
  const across = view === 'slant' ? m.range_bin_m : view === 'geocoded' ? state.scene.cell_m : 0;
  drawScaleBar($('image-scalebar'), $('image'), run.kind === 'ppi' ? 0 : across);
  if (view === 'slant') $('image-scalebar').querySelector('span').textContent += ' (slant range)';
}

// ---- legend and overlay key ----
function showLegend() {
  const m = run.map || {};
  $('legend').innerHTML = (m.legend || []).map((c) =>
    `<span data-category="${c.id}" data-rgb="${c.rgb.join(',')}"><span class="swatch" ` +
    `style="background: rgb(${c.rgb.join(',')})"></span>${c.id}: ${c.name || '?'}</span>`)
    .join('');
  const shown = overlayMasks().split(',').filter((x) => x);
  $('overlay-key').innerHTML = (m.overlay_key || [])
    .filter((k) => shown.includes(k.mask))
    .map((k) => `<span data-mask="${k.mask}" data-rgba="${k.rgba.join(',')}"><span ` +
      `class="swatch" style="background: rgba(${k.rgba.slice(0, 3).join(',')},` +
      `${(k.rgba[3] / 255).toFixed(2)})"></span>${k.mask}</span>`).join('');
}

// ---- contrast stretch and colour ramps (an SVG filter on the picture) ----
const ramps = {
  grey: (t) => [t, t, t],
  inverted: (t) => [1 - t, 1 - t, 1 - t],
  // Viridis at five stops (matplotlib's), linearly between.
  viridis: (t) => lerpStops([[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98],
                             [253, 231, 37]], t),
  hot: (t) => [Math.min(1, 3 * t), Math.min(1, Math.max(0, 3 * t - 1)),
               Math.min(1, Math.max(0, 3 * t - 2))],
};

function lerpStops(stops, t) {
  const x = t * (stops.length - 1);
  const i = Math.min(stops.length - 2, Math.floor(x));
  const f = x - i;
  return [0, 1, 2].map((c) => (stops[i][c] + f * (stops[i + 1][c] - stops[i][c])) / 255);
}

function applyStretch() {
  let lo = Number($('stretch-low').value);
  let hi = Number($('stretch-high').value);
  if (hi <= lo) hi = lo + 1;
  $('stretch-low-value').textContent = lo;
  $('stretch-high-value').textContent = hi;
  const ramp = ramps[$('ramp').value] || ramps.grey;
  const tables = [[], [], []];
  for (let k = 0; k <= 255; k += 1) {
    const t = Math.min(1, Math.max(0, (k - lo) / (hi - lo)));
    ramp(t).forEach((v, c) => tables[c].push(v.toFixed(4)));
  }
  ['r', 'g', 'b'].forEach((ch, c) => {
    const f = $(`ramp-${ch}`);
    f.setAttribute('type', 'table');
    f.setAttribute('tableValues', tables[c].join(' '));
  });
  // The colour bar: greytones 0..255 as the picture shows them now.
  const stops = [];
  for (let k = 0; k <= 255; k += 15) {
    const rgb = [0, 1, 2].map((c) => Math.round(255 * Number(tables[c][k])));
    stops.push(`rgb(${rgb.join(',')}) ${((k / 255) * 100).toFixed(1)}%`);
  }
  $('colour-bar').style.background = `linear-gradient(to right, ${stops.join(', ')})`;
}

function autoStretch() {
  if (!lastHistogram) return;
  const counts = lastHistogram.slice(1);  // 0 is shadow: left out
  const total = counts.reduce((a, b) => a + b, 0);
  let acc = 0, lo = 0, hi = 255;
  for (let k = 0; k < counts.length; ++k) {
    acc += counts[k];
    if (acc < 0.02 * total) lo = k + 1;
    if (acc <= 0.98 * total) hi = k + 2;
  }
  $('stretch-low').value = lo;
  $('stretch-high').value = Math.max(lo + 1, Math.min(255, hi));
  applyStretch();
}

// ---- the linked cursor ----
function markCursor(id, x, y, img, view) {
  const c = $(id);
  if (!img.naturalWidth) return;
  c.hidden = false;
  c.style.left = `${((x + 0.5) / img.naturalWidth) * 100}%`;
  c.style.top = `${((y + 0.5) / img.naturalHeight) * 100}%`;
  c.dataset.col = x;
  c.dataset.row = y;
  c.dataset.view = view || '';
}

function markMap(col, row) {
  if (!map) return;
  const s = state.scene;
  const ll = [(s.rows - row - 0.5) * s.cell_m, (col + 0.5) * s.cell_m];
  if (!mapLayers.marker) {
    mapLayers.marker = L.circleMarker(ll, { radius: 7, color: '#00e5ff', weight: 2, fill: false })
      .addTo(map);
  } else {
    mapLayers.marker.setLatLng(ll);
  }
  const el = mapLayers.marker.getElement();
  if (el) { el.dataset.col = col; el.dataset.row = row; el.id = 'map-cursor'; }
}

// An inspected place, marked in the other view(s).
function linkCursor(view, x, y, body) {
  const imageView = $('image').dataset.view;
  if (view === 'scene' || view === 'geocoded') {
    markCursor('scene-cursor', x, y, $('scene'), 'scene');
    if (imageView === 'geocoded') {
      if (hasLeaflet()) markMap(x, y); else markCursor('image-cursor', x, y, $('image'), 'geocoded');
    } else if (imageView === 'slant' && body.pixel) {
      markCursor('image-cursor', body.pixel.bin, body.pixel.line, $('image'), 'slant');
    } else {
      $('image-cursor').hidden = true;
    }
  } else {
    markCursor('image-cursor', x, y, $('image'), view);
    if (body.scene_col !== undefined) {
      markCursor('scene-cursor', body.scene_col, body.scene_row, $('scene'), 'scene');
    }
  }
}

async function showRun(summary) {
  run = summary;
  const extra = summary.film_only ? ' (film only)' : '';
  setStatus(`run ${run.id}: ${(1000 * run.seconds).toFixed(0)} ms${extra}` +
            (run.shadow_percent !== undefined
              ? `; shadow ${run.shadow_percent.toFixed(1)}%, layover ${run.layover_percent.toFixed(1)}%`
              : ''));
  await showImages();
  showLegend();
  drawHistogram();
  await refreshRuns().catch(() => {});
  if ($('compare-mode').value !== 'off') await showCompare();
  if (run.kind !== 'ppi') {
    api('/api/shadowmap.txt').then(({ body }) => { $('shadow-map').textContent = body; })
      .catch(() => {});
  } else {
    $('shadow-map').textContent = '(no shadow map for a PPI)';
  }
  if (!summary.film_only) drawSigma0();
  if ($('sensor-kind').value !== 'off') showSensor();
}

// ---- other sensors (GET /api/sensor/<kind>.png: ris sensor's scene-grid preview) ----
function sensorMinute() {
  const minute = Number($('sensor-time').value);
  const hh = String(Math.floor(minute / 60)).padStart(2, '0');
  $('sensor-time-value').textContent = `${hh}:${String(minute % 60).padStart(2, '0')}`;
  return minute;
}

async function showSensor() {
  const kind = $('sensor-kind').value;
  const img = $('sensor-image');
  const minute = sensorMinute();
  if (kind === 'off') {
    img.hidden = true;
    img.removeAttribute('src');
    return;
  }
  // The scene's version (an edit makes a new picture): from the scene image's URL.
  const version = (run && run.images.scene || '').split('scene=')[1] || '';
  const url = `/api/sensor/${kind}.png?minute=${minute}&scene=${version}`;
  img.hidden = false;
  img.dataset.state = 'loading';
  setStatus(`rendering the ${kind} view…`);
  const ok = await loadImage(img, url);
  img.dataset.state = ok ? 'ready' : 'failed';
  if (ok) {
    setStatus(`${kind} view at ${$('sensor-time-value').textContent} UTC`);
    return;
  }
  img.hidden = true;
  try {
    await api(url);
  } catch (e) {
    showError(e.message);
  }
}

// ---- charts ----
const palette = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b', '#e377c2',
                 '#7f7f7f', '#bcbd22', '#17becf'];

let sigma0Chart = null;
let histogramChart = null;
let lastHistogram = null;

async function drawSigma0() {
  const { body } = await api('/api/sigma0');
  if (hasChart()) {
    const datasets = body.curves.map((cv, i) => ({
      label: `${cv.category}: ${cv.name}`, data: cv.sigma0_db, borderColor: palette[i % 10],
      backgroundColor: palette[i % 10], pointRadius: 0, borderWidth: 1.5, spanGaps: false }));
    const title = `sigma0 at ${(body.frequency_hz / 1e9).toFixed(2)} GHz`;
    if (!sigma0Chart) {
      sigma0Chart = new Chart($('sigma0-chart'), {
        type: 'line', data: { labels: body.angles_deg, datasets },
        options: { animation: false, responsive: false,
          plugins: { title: { display: true, text: title }, legend: { labels: { boxWidth: 10 } } },
          scales: { x: { title: { display: true, text: 'local incidence angle, deg' },
                         ticks: { maxTicksLimit: 10 } },
                    y: { title: { display: true, text: 'sigma0, dB' }, suggestedMin: -40 } } } });
    } else {
      sigma0Chart.data.labels = body.angles_deg;
      sigma0Chart.data.datasets = datasets;
      sigma0Chart.options.plugins.title.text = title;
      sigma0Chart.update();
    }
    return;
  }
  drawSigma0Canvas(body);
}

// Without Chart.js: the same curves drawn by hand, with labelled axes.
function drawSigma0Canvas(body) {
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
  lastHistogram = body.counts;
  const labels = body.counts.map((_, k) => k);
  if (hasChart()) {
    if (!histogramChart) {
      histogramChart = new Chart($('histogram'), {
        type: 'bar', data: { labels, datasets: [{ label: 'slant pixels', data: body.counts,
          backgroundColor: '#3d4a63', barPercentage: 1, categoryPercentage: 1 }] },
        options: { animation: false, responsive: false, plugins: { legend: { display: false } },
          scales: { x: { title: { display: true, text: 'greytone (0 black .. 255 white)' },
                         ticks: { maxTicksLimit: 9 } },
                    y: { title: { display: true, text: 'pixels' }, type: 'logarithmic' } } } });
    } else {
      histogramChart.data.datasets[0].data = body.counts;
      histogramChart.update();
    }
    return;
  }
  const c = $('histogram');
  const g = c.getContext('2d');
  g.clearRect(0, 0, c.width, c.height);
  // Scaled to the tallest bar between the ends: shadow (0) and saturation
  // (255) spikes would flatten the rest; they are drawn clipped.
  const max = Math.max(1, ...body.counts.slice(1, 255));
  const bottom = c.height - 14;
  const w = c.width / 256;
  g.fillStyle = '#3d4a63';
  body.counts.forEach((n, k) => {
    const h = Math.min(1, n / max) * (bottom - 4);
    g.fillRect(k * w, bottom - h, Math.max(w, 1), h);
  });
  g.fillStyle = '#555';
  g.font = '10px sans-serif';
  for (const k of [0, 64, 128, 192, 255]) g.fillText(String(k), k * w, c.height - 2);
  g.fillText(`greytone; pixels up to ${max}`, c.width - 150, 10);
}

// ---- zoom, pan and click on a viewport ----
// paint (optional): {active(), down(x, y), move(x, y), up()} in image pixels;
// while active, dragging paints instead of panning.
// onView (optional): called after the user zooms or pans (the linked zoom).
function makeZoomable(viewport, stage, img, onClick, paint, onView) {
  const t = { scale: 1, x: 0, y: 0 };
  const apply = (user) => {
    stage.style.transform = `translate(${t.x}px, ${t.y}px) scale(${t.scale})`;
    updateScaleBars();
    if (user && onView) onView();
  };
  // The picture's laid-out size (its true aspect may differ from its
  // pixels', applyAspect).
  const fit = () => {
    if (!img.naturalWidth || !img.offsetWidth) return;
    t.scale = Math.min(viewport.clientWidth / img.offsetWidth,
                       viewport.clientHeight / img.offsetHeight);
    t.x = 0; t.y = 0;
    apply();
  };
  // Fit the first picture, and again when the size changes (another
  // presentation); keep the user's zoom across runs of the same size.
  let fittedSize = '';
  const refit = () => {
    const size = `${img.offsetWidth}x${img.offsetHeight}`;
    if (size !== fittedSize) { fittedSize = size; fit(); }
  };
  img.addEventListener('load', refit);
  img.addEventListener('resized', refit);
  viewport.addEventListener('dblclick', () => { fit(); if (onView) onView(); });
  viewport.addEventListener('wheel', (ev) => {
    ev.preventDefault();
    const r = viewport.getBoundingClientRect();
    const px = ev.clientX - r.left, py = ev.clientY - r.top;
    const k = ev.deltaY < 0 ? 1.25 : 0.8;
    t.x = px - (px - t.x) * k; t.y = py - (py - t.y) * k; t.scale *= k;
    apply(true);
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
    if (drag && drag.moved && onView) onView();
    if (drag && !drag.moved && viewport.contains(ev.target)) {
      const r = img.getBoundingClientRect();
      const x = Math.floor(((ev.clientX - r.left) / r.width) * img.naturalWidth);
      const y = Math.floor(((ev.clientY - r.top) / r.height) * img.naturalHeight);
      if (x >= 0 && y >= 0 && x < img.naturalWidth && y < img.naturalHeight) onClick(x, y);
    }
    drag = null;
  });
  return {
    // Shows image pixels x0..x1, y0..y1 (fractional) filling the viewport.
    showRegion(x0, y0, x1, y1) {
      if (!img.naturalWidth || !img.offsetWidth) return;
      const kx = img.offsetWidth / img.naturalWidth, ky = img.offsetHeight / img.naturalHeight;
      t.scale = Math.min(viewport.clientWidth / ((x1 - x0) * kx),
                         viewport.clientHeight / ((y1 - y0) * ky));
      t.x = viewport.clientWidth / 2 - t.scale * kx * (x0 + x1) / 2;
      t.y = viewport.clientHeight / 2 - t.scale * ky * (y0 + y1) / 2;
      apply();
    },
    // The image pixels the viewport shows, [x0, y0, x1, y1], within the image.
    region() {
      if (!img.naturalWidth || !img.offsetWidth) return null;
      const kx = t.scale * img.offsetWidth / img.naturalWidth;
      const ky = t.scale * img.offsetHeight / img.naturalHeight;
      const r = [Math.max(0, -t.x / kx), Math.max(0, -t.y / ky),
                 Math.min(img.naturalWidth, (viewport.clientWidth - t.x) / kx),
                 Math.min(img.naturalHeight, (viewport.clientHeight - t.y) / ky)];
      return r[2] > r[0] && r[3] > r[1] ? r : null;
    },
  };
}

// ---- linked zoom between the scene and the slant view ----
// The other view shows the region the server maps this one's to, through
// the slant image's own (line, range) mapping (GET /api/link). Answers to
// an older move are dropped.
let linkTicket = 0;
async function linkViews(from) {
  if (!$('link-zoom').checked || !run || run.kind === 'ppi' || !sceneView || !imageView) return;
  if ($('image').dataset.view !== 'slant' || !$('map').hidden) return;
  const [src, dst] = from === 'scene' ? [sceneView, imageView] : [imageView, sceneView];
  const r = src.region();
  if (!r) return;
  const ticket = ++linkTicket;
  try {
    const q = new URLSearchParams({ from, x0: r[0], y0: r[1], x1: r[2], y1: r[3] });
    const { body } = await api(`/api/link?${q}`);
    if (ticket !== linkTicket) return;
    dst.showRegion(body.x0, body.y0, body.x1, body.y1);
    $('image-viewport').dataset.linked = `${from}:${ticket}`;
  } catch (e) {
    // A region that images nothing in the other view: that view stays.
  }
}

// ---- the pixel inspector ----
const inspectorRows = [
  ['view', 'view'], ['row', 'row'], ['col', 'col'], ['line', 'line'], ['bin', 'bin'],
  ['ground_range_m', 'ground range, m'],
  ['lat_deg', 'latitude, deg'], ['lon_deg', 'longitude, deg'], ['datum', 'datum'],
  ['x_m', 'map x (east), m'], ['y_m', 'map y (north), m'],
  ['scene_row', 'scene row'], ['scene_col', 'scene col'],
  ['elevation_m', 'elevation, m'], ['category_name', 'category'], ['category', 'category id'],
  ['local_incidence_deg', 'local incidence, deg'], ['sigma0_db', 'sigma0 (library), dB'],
  ['slant_range_m', 'slant range, m'], ['incidence_deg', 'incidence, deg'],
  ['incidence_flat_deg', 'incidence (flat), deg'], ['looks', 'N (looks)'],
  ['mean_power_w', 'mean power, W'], ['mean_power_dbw', 'mean power, dBW'],
  ['speckled_power_w', 'speckled power, W'], ['speckled_power_dbw', 'speckled power, dBW'],
  ['greytone', 'greytone'], ['flags', 'flags'],
];
// The slant pixel's calibrated readout (pixel.calibrated: the power over the
// flat reference's radar equation, as sigma0_slant.tif), beside the watts.
const calibratedRows = [
  ['sigma0_db', 'sigma0 (calibrated), dB'], ['beta0_db', 'beta0, dB'],
  ['gamma0_db', 'gamma0, dB'], ['speckled_sigma0_db', 'speckled sigma0, dB'],
  ['incidence_deg', 'incidence at reference, deg'],
  ['reference_height_m', 'calibration reference height, m'],
  ['not_calibrated', 'calibration'],
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
    // Powers in dB beside watts (sigma0 is given in dB by the server).
    const withDb = (o) => {
      if (o && o.speckled_power_w > 0) o.speckled_power_dbw = 10 * Math.log10(o.speckled_power_w);
    };
    withDb(body);
    withDb(body.pixel);
    linkCursor(view, x, y, body);
    const rows = [];
    const add = (obj, prefix, table = inspectorRows, keyPrefix = '') => {
      for (const [key, label] of table) {
        const v = key.endsWith('_deg') && key.startsWith('l') && typeof obj[key] === 'number'
          ? obj[key].toFixed(6) : fmtValue(obj[key]);
        if (key in obj) rows.push(`<tr><td>${prefix}${label}</td>` +
                                  `<td data-key="${keyPrefix}${key}">${v}</td></tr>`);
      }
    };
    add(body, '');
    const slant = body.pixel || body;
    if (slant.calibrated) add(slant.calibrated, '', calibratedRows, 'calibrated.');
    if (body.pixel) add(body.pixel, 'pixel ');
    if (compare && slant.bin !== undefined) rows.push(...await compareRows(slant.bin, slant.line));
    $('inspector').innerHTML = rows.join('');
    showError('');
  } catch (e) {
    showError(e.message);
  }
}

// ---- comparing two runs (the slant view) ----
// The inspector's rows for the compared runs at slant pixel (bin, line):
// the earlier run's powers and the difference view's value (data-value: the
// number unrounded).
async function compareRows(bin, line) {
  const c = compare;
  const xy = `x=${bin}&y=${line}`;
  try {
    const [{ body: then }, { body: d }] = await Promise.all([
      api(`/api/inspect?view=slant&run=${c.earlier}&${xy}`),
      api(`/api/compare/pixel?earlier=${c.earlier}&quantity=${c.quantity}&${xy}`)]);
    const row = (label, key, v) => `<tr><td>${label}</td><td data-key="${key}" ` +
      `data-value="${v === null ? '' : v}">${fmtValue(v)}</td></tr>`;
    return [row('earlier run', 'compare.earlier', then.run),
            row('earlier mean power, W', 'compare.earlier_mean_power_w', then.mean_power_w),
            row('earlier speckled power, W', 'compare.earlier_speckled_power_w',
                then.speckled_power_w),
            row(`difference (${c.quantity}), dB`, 'compare.difference_db', d.difference_db)];
  } catch (e) {
    return [`<tr><td>compare</td><td>${e.message}</td></tr>`];
  }
}

// The earlier runs, newest first; one on another grid is listed too and
// refused with the server's reason when chosen.
async function refreshRuns() {
  const sel = $('compare-run');
  if (!run || run.kind === 'ppi') { sel.innerHTML = ''; return; }
  const { body } = await api('/api/runs');
  const keep = sel.value;
  const earlier = body.runs.filter((k) => k.id !== body.current).reverse();
  sel.innerHTML = earlier.map((k) => `<option value="${k.id}">${k.label}` +
    `${k.comparable ? '' : ' (another grid)'}</option>`).join('');
  const ids = earlier.map((k) => String(k.id));
  const comparable = earlier.filter((k) => k.comparable).map((k) => String(k.id));
  sel.value = ids.includes(keep) ? keep : (comparable[0] || ids[0] || '');
}

function applySwipe() {
  // Left of the slider the current run, right of it the earlier one.
  $('compare-image').style.clipPath = `inset(0 0 0 ${$('compare-swipe').value}%)`;
}

function drawDifferenceKey(c) {
  const n = c.key.length - 1;
  const stops = c.key.map((k, i) => `rgb(${k.rgb.join(',')}) ${((100 * i) / n).toFixed(1)}%`);
  $('difference-bar').style.background = `linear-gradient(to right, ${stops.join(', ')})`;
  $('difference-low').textContent = `${-c.range_db}`;
  $('difference-high').textContent = `+${c.range_db}`;
  $('difference-key').dataset.key = JSON.stringify(c.key);
  $('difference-key').dataset.range = c.range_db;
  $('difference-key').hidden = false;
}

async function showCompare() {
  const mode = $('compare-mode').value;
  const img = $('compare-image');
  const diff = $('difference-image');
  $('swipe-label').hidden = mode !== 'swipe';
  img.classList.toggle('side', mode === 'side');
  img.style.clipPath = '';
  $('difference-key').hidden = true;
  compare = null;
  const off = () => { img.hidden = true; setOverlay(diff, ''); };
  if (mode === 'off' || !run || run.kind === 'ppi') {
    off();
    $('compare-note').textContent = run && run.kind === 'ppi' && mode !== 'off'
      ? 'a PPI run has no slant image to compare' : '';
    return;
  }
  const earlier = $('compare-run').value;
  if (!earlier) {
    off();
    $('compare-note').textContent = 'no earlier run yet: change the band (or anything but the ' +
      'geometry) and compare the two';
    return;
  }
  if (currentView() !== 'slant') { $('presentation').value = 'slant'; await showImages(); }
  try {
    const q = new URLSearchParams({ earlier, quantity: $('compare-quantity').value });
    const { body } = await api(`/api/compare?${q}`);
    compare = body;
    if (mode === 'difference') {
      img.hidden = true;
      await setOverlay(diff, body.images.difference);
      drawDifferenceKey(body);
      $('compare-note').textContent = `10 log10(run ${body.current} / run ${body.earlier}) of ` +
        `the ${body.quantity} power`;
    } else {
      await setOverlay(diff, '');
      await loadImage(img, body.images.earlier);
      img.hidden = false;
      img.dataset.run = body.earlier;
      if (mode === 'swipe') applySwipe();
      const i = $('image');
      if (mode === 'side' && imageView) imageView.showRegion(0, 0, 2 * i.naturalWidth + 2, i.naturalHeight);
      $('compare-note').textContent = mode === 'side'
        ? `left: ${body.current_label}; right: ${body.earlier_label}`
        : `left of the slider: ${body.current_label}; right: ${body.earlier_label}`;
    }
    showError('');
  } catch (e) {
    off();
    $('compare-note').textContent = e.message;
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
  // Optional keys the file left out are shown at their defaults, so they
  // can be set (a pyramid's rotation; docs/scene-format.md).
  const withDefaults = { ...o };
  if (o.type !== 'hemisphere' && o.type !== 'tower' && !('rotation' in o)) {
    withDefaults.rotation = 0;
  }
  for (const [k, v] of Object.entries(withDefaults)) {
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

// The length unit the description writes its objects in ("300 ft"):
// new objects and moves are written in it, not in metres beside feet.
const metresPer = { m: 1, km: 1000, cm: 0.01, mm: 0.001, ft: 0.3048, mi: 1609.344,
                    nmi: 1852 };
function sceneUnit() {
  const d = (state && state.scene.description) || {};
  const samples = [...objects().flatMap((o) => [o.x, o.y, o.length, o.base]),
                   d.grid && d.grid.cell_size, d.cell_size];
  for (const v of samples) {
    const m = typeof v === 'string' && v.trim().match(/^[-+0-9.eE]+\s*([a-z]+)$/);
    if (m && metresPer[m[1]]) return m[1];
  }
  return 'm';
}

// A length in metres as the description writes lengths: a bare number of
// metres, or a whole number of its unit ("984 ft").
function lengthValue(metres) {
  const u = sceneUnit();
  return u === 'm' ? Math.round(metres) : `${Math.round(metres / metresPer[u])} ${u}`;
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
                             { x: lengthValue(xm), y: lengthValue(ym) }));
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
    addObject({ type: 'box', x: lengthValue(c.x), y: lengthValue(c.y), length: lengthValue(300),
                width: lengthValue(300), height: lengthValue(150), rotation: 0, category: 5 });
  });
  $('add-pyramid').addEventListener('click', () => {
    const c = sceneCentre();
    addObject({ type: 'pyramid', x: lengthValue(c.x), y: lengthValue(c.y), base: lengthValue(400),
                height: lengthValue(200), rotation: 0, category: 4 });
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

// ---- bring your own data (POST /api/upload, the file's bytes) ----
async function uploadFile() {
  const file = $('upload-file').files[0];
  if (!file) { showError('choose a file to upload first'); return; }
  const kind = $('upload-kind').value;
  const q = new URLSearchParams({ kind, name: file.name });
  if (kind === 'landcover') q.set('mapping', $('upload-mapping').value);
  setStatus(`uploading ${file.name}…`);
  try {
    // octet-stream: like JSON, a type no other page can send without a
    // preflight the server never approves (docs/serve.md, "Threat model").
    const { body } = await api(`/api/upload?${q}`, {
      method: 'POST', headers: { 'Content-Type': 'application/octet-stream' }, body: file });
    await loadState();
    $('upload-note').textContent =
      `${body.uploaded}: simulated with ${body.backscatter}`;
    if (map) { map.fitBounds(sceneBounds()); }
    showError('');
    await showRun(body.run);
  } catch (e) {
    showError(e.message);
    setStatus('upload refused');
  }
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
  // A SAR's range resolution comes from its chirp, not a pulse width.
  const sar = p.mode === 'sar';
  $('pulse-width-label').hidden = sar;
  $('bandwidth-label').hidden = !sar;
  $('pulse-width').value = (p.pulse_width_s * 1e9).toFixed(1);
  if (sar && p.sar && p.sar.bandwidth_hz) $('bandwidth').value = (p.sar.bandwidth_hz / 1e6).toFixed(1);
  $('density-range').value = p.film.density_range;
  $('gamma').value = p.film.gamma;
  $('fading').checked = p.film.terms.fading;
  $('seed').value = state.seed;
  // The current radar's file is the selected preset; a changed description
  // shows as such (the list is never blank).
  const presets = state.radar_presets.includes(state.radar.file)
    ? state.radar_presets : [state.radar.file, ...state.radar_presets];
  fillSelect($('radar-preset'), presets, state.radar.file);
  $('allow-extrapolation').checked = !!state.allow_extrapolation;
  $('upload-mapping').innerHTML = (state.landcover_mappings || [])
    .map((n) => `<option${n === 'esa-worldcover.toml' ? ' selected' : ''}>${n}</option>`).join('');
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
  imageView = makeZoomable($('image-viewport'), $('image-stage'), $('image'),
                           (x, y) => inspect($('image').dataset.view || 'slant', x, y), null,
                           () => linkViews('slant'));
  sceneView = makeZoomable($('scene-viewport'), $('scene-stage'), $('scene'), onSceneClick,
                           scenePaint, () => linkViews('scene'));
  for (const id of ['compare-mode', 'compare-run', 'compare-quantity']) {
    $(id).addEventListener('change', showCompare);
  }
  $('compare-swipe').addEventListener('input', applySwipe);
  for (const el of document.querySelectorAll('[data-radar], [data-top]')) {
    el.addEventListener(el.type === 'range' ? 'input' : 'change', onControl);
  }
  $('radar-preset').addEventListener('change', async (ev) => {
    if (ev.target.value === state.radar.file) return;
    pending = {};
    try {
      const { body } = await postJson('/api/simulate', { radar_preset: ev.target.value });
      await loadState();
      await showRun(body);
    } catch (e) {
      showError(e.message);
    }
  });
  $('presentation').addEventListener('change', async () => {
    // Runs are compared on the slant view: another presentation ends it.
    if (currentView() !== 'slant' && $('compare-mode').value !== 'off') {
      $('compare-mode').value = 'off';
      await showCompare();
    }
    showImages();
  });
  for (const c of document.querySelectorAll('.overlay')) {
    c.addEventListener('change', () => { showImages(); showLegend(); });
  }
  $('sensor-kind').addEventListener('change', showSensor);
  $('sensor-time').addEventListener('input', sensorMinute);
  $('sensor-time').addEventListener('change', showSensor);
  sensorMinute();
  $('overlay-opacity').addEventListener('input', applyOpacity);
  for (const id of ['stretch-low', 'stretch-high']) $(id).addEventListener('input', applyStretch);
  $('ramp').addEventListener('change', applyStretch);
  $('stretch-auto').addEventListener('click', autoStretch);
  $('upload').addEventListener('click', uploadFile);
  $('upload-kind').addEventListener('change', () => {
    $('mapping-label').hidden = $('upload-kind').value !== 'landcover';
  });
  $('mapping-label').hidden = true;
  window.addEventListener('resize', updateScaleBars);
  const missing = [];
  if (!hasLeaflet()) missing.push('Leaflet (libjs-leaflet): the geocoded view is a plain image');
  if (!hasChart()) missing.push('Chart.js (libjs-chart.js): charts are drawn without it');
  $('lib-note').textContent = missing.length
    ? `Not installed: ${missing.join('; ')}. scripts/install-deps.sh installs them.` : '';
  applyStretch();
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
