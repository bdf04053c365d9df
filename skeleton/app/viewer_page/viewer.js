// The viewer page: polls the server's status, redraws the image when it
// changes, and turns mouse and form input into the server's JSON requests.
// Plain JavaScript, no libraries: it fetches only from the server that served it.
'use strict';

const $ = (id) => document.getElementById(id);
const canvas = $('canvas'), ctx = canvas.getContext('2d');
const view = {
  status: null, image: null, show: 'render', mode: 'camera', shownVersion: -1, fetching: false,
  bvhPath: '', bvh: null, path: null, drag: null, cell: null, updates: [],
};
window.viewer = view;  // for the browser test and the curious

const helpText = {
  camera: 'Drag: orbit about the target. Shift-drag or right-drag: pan. Wheel: zoom.',
  cell: 'Drag a rectangle: only that cell renders. Double-click: the whole image again.',
  bvh: 'Blue: the node\'s box. Yellow: its primitives. Step with the buttons or the keys L, R, P (parent), T (root).',
  inspect: 'Click a pixel: its value, samples, and one path traced through it, drawn over the image.',
};

function message(text) { $('message').textContent = text || ''; }

async function api(method, url, body) {
  const init = { method };
  if (body !== undefined) { init.body = JSON.stringify(body); init.headers = { 'Content-Type': 'application/json' }; }
  const res = await fetch(url, init);
  const type = res.headers.get('Content-Type') || '';
  const data = type.startsWith('application/json') ? await res.json() : await res.arrayBuffer();
  if (!res.ok) throw new Error((data && data.error) || (res.status + ' ' + res.statusText));
  return { data, res };
}
function act(promise) { return promise.then((r) => { message(''); return r; }, (e) => { message(e.message); }); }

// ---- image and overlay ----------------------------------------------------
async function fetchImage() {
  if (view.fetching) return;
  view.fetching = true;
  try {
    const version = view.status.version;
    const { data, res } = await api('GET', '/api/image?kind=' + view.show);
    const w = +res.headers.get('X-Width'), h = +res.headers.get('X-Height');
    view.image = new ImageData(new Uint8ClampedArray(data), w, h);
    view.shownVersion = view.show === 'render' || view.show === 'rate' ? version : -2;
    const now = performance.now();
    view.updates = view.updates.filter((t) => now - t < 5000).concat([now]);
    draw();
  } catch (e) {
    message(e.message);
    if (view.show !== 'render') { view.show = 'render'; $('show').value = 'render'; }
  } finally {
    view.fetching = false;
  }
}

function line(segments, colour, width) {
  ctx.strokeStyle = colour;
  ctx.lineWidth = width;
  ctx.beginPath();
  for (const [x0, y0, x1, y1] of segments) { ctx.moveTo(x0, y0); ctx.lineTo(x1, y1); }
  ctx.stroke();
}

// The canvas is drawn at screen size: the image scaled up without smoothing
// (one block per pixel), the overlays on top in image coordinates, with
// lines a couple of screen pixels wide whatever the scale.
const imageCanvas = document.createElement('canvas');
function draw() {
  if (!view.image) return;
  const w = view.image.width, h = view.image.height;
  const fit = Math.min(960 / w, 720 / h), scale = fit >= 1 ? Math.floor(fit) : fit;
  if (canvas.width !== Math.round(w * scale) || canvas.height !== Math.round(h * scale)) {
    canvas.width = Math.round(w * scale);
    canvas.height = Math.round(h * scale);
  }
  imageCanvas.width = w;
  imageCanvas.height = h;
  imageCanvas.getContext('2d').putImageData(view.image, 0, 0);
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(imageCanvas, 0, 0, canvas.width, canvas.height);
  ctx.setTransform(canvas.width / w, 0, 0, canvas.height / h, 0, 0);
  const px = w / canvas.width;  // one screen pixel in image pixels
  if (view.mode === 'bvh' && view.bvh) {
    line(view.bvh.primitive_segments, 'rgba(255,220,0,0.8)', px);
    line(view.bvh.box_segments, '#3af', 2 * px);
  }
  if (view.path) drawPath(px);
  const c = view.drag && view.mode === 'cell' ? view.drag.rect : null;
  if (c) { ctx.strokeStyle = '#0f0'; ctx.lineWidth = 2 * px; ctx.strokeRect(c[0], c[1], c[2] - c[0], c[3] - c[1]); }
}

function drawPath(px) {
  const pts = [[view.path.x + 0.5, view.path.row + 0.5]];
  for (const v of view.path.vertices) if (v.pixel) pts.push(v.pixel);
  ctx.strokeStyle = '#f0f';
  ctx.lineWidth = 2 * px;
  ctx.beginPath();
  pts.forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
  ctx.stroke();
  const bad = view.path.warnings.length > 0 || view.path.error;
  for (const [x, y] of pts.slice(1)) {
    ctx.fillStyle = bad ? '#f00' : '#fff';
    ctx.beginPath(); ctx.arc(x, y, 4 * px, 0, 2 * Math.PI); ctx.fill();
  }
}

// ---- status -----------------------------------------------------------------
function duration(s) { return s < 60 ? s.toFixed(1) + ' s' : Math.floor(s / 60) + ' min ' + Math.round(s % 60) + ' s'; }
function fmt(x, digits = 3) { return x === null || x === undefined ? 'NaN' : Number(x).toPrecision(digits); }

async function poll() {
  try {
    const { data } = await api('GET', '/api/status');
    const first = !view.status;
    view.status = data;
    if (first || view.refillForm) fillForm(data.settings);
    if (first && data.state === 'stopped') act(api('POST', '/api/control?action=restart'));  // a reloaded page
    view.refillForm = false;
    // Overlays are projections through the camera: redo them when it changes.
    const key = JSON.stringify([data.camera, data.settings.width, data.settings.height]);
    if (view.cameraKey && key !== view.cameraKey) {
      view.path = null;
      $('pixel-info').textContent = 'The view changed: click a pixel again.';
      if (view.bvh) walk(view.bvhPath);
    }
    view.cameraKey = key;
    const rate = view.updates.length / 5;
    $('status').textContent = `${data.state} · ${data.spp.toFixed(1)}/${data.target_spp} spp · ` +
      `${fmt(data.rays_per_second / 1e6)} Mrays/s · ETA ${duration(data.eta_seconds)} · ` +
      `${data.settings.width}×${data.settings.height}, ${data.threads} threads · page ${rate.toFixed(1)} updates/s`;
    $('error').style.display = data.error ? 'block' : 'none';
    $('error').textContent = data.error ? 'A task threw: ' + data.error + (data.hint ? '\n' + data.hint : '') +
      '\nThe server is still up: fix the task, rebuild, and run --view again.' : '';
    $('pause').textContent = data.state === 'paused' ? 'Resume' : 'Pause';
    $('camera-file').textContent = cameraText(data);
    if (view.shownVersion !== data.version && (view.show === 'render' || view.show === 'rate')) fetchImage();
    if (view.show === 'difference' || $('compare-info').dataset.live) refreshCompare();
  } catch (e) {
    $('status').textContent = 'the viewer is not answering (' + e.message + '): was it stopped?';
  }
  setTimeout(poll, 200);
}

function cameraText(s) {
  return JSON.stringify(s.camera) + '\n\n./build/pathtracer -c camera.json ' + s.scene + ' -r ' + s.settings.width + ' ' +
    s.settings.height + ' -s ' + s.settings.samples + ' -l ' + s.settings.light_samples + ' -m ' + s.settings.max_depth;
}

function fillForm(st) {
  for (const k of ['samples', 'light_samples', 'max_depth', 'rr', 'width', 'height', 'exposure']) $(k).value = st[k];
  $('accumulate').value = String(st.accumulate);
  $('hemisphere').checked = st.hemisphere;
  $('adaptive').checked = !!st.adaptive;
  if (st.adaptive) { $('batch').value = st.adaptive[0]; $('tolerance').value = st.adaptive[1]; }
}

// ---- settings and buttons ----------------------------------------------------
function settingsFromForm() {
  const n = (id) => Number($(id).value);
  return {
    samples: n('samples'), light_samples: n('light_samples'), max_depth: n('max_depth'), accumulate: n('accumulate'),
    hemisphere: $('hemisphere').checked, rr: n('rr'), width: n('width'), height: n('height'), exposure: n('exposure'),
    adaptive: $('adaptive').checked ? [n('batch'), n('tolerance')] : null,
  };
}
document.querySelectorAll('#settings input, #settings select').forEach((el) =>
  el.addEventListener('change', () => { view.shownVersion = -1; act(api('POST', '/api/settings', settingsFromForm())); }));

$('pause').onclick = () => act(api('POST', '/api/control?action=' + (view.status.state === 'paused' ? 'resume' : 'pause')));
$('restart').onclick = () => act(api('POST', '/api/control?action=restart'));
$('stop').onclick = () => act(api('POST', '/api/control?action=stop'));
$('reset-scene').onclick = () => act(api('POST', '/api/camera/reset?to=scene'));
$('reset-course').onclick = () => act(api('POST', '/api/camera/reset?to=course'));
$('save-camera').onclick = async () => {
  const r = await act(api('GET', '/api/camera'));
  if (!r) return;
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([JSON.stringify(r.data, null, 2) + '\n'], { type: 'application/json' }));
  a.download = 'camera.json';
  a.click();
  message('Saved camera.json: render it with the command under "Camera".');
};
$('show').onchange = () => { view.show = $('show').value; view.shownVersion = -1; fetchImage(); refreshCompare(); };
function flip() {
  view.show = view.show === 'reference' ? 'render' : 'reference';
  $('show').value = view.show;
  view.shownVersion = -1;
  fetchImage();
  refreshCompare();
}
$('flip').onclick = flip;
$('library-settings').onclick = () => act(api('POST', '/api/compare/library-settings').then((r) => { view.refillForm = true; return r; }));

async function refreshCompare() {
  const r = await act(api('GET', '/api/compare'));
  if (!r) return;
  const c = r.data, el = $('compare-info');
  el.dataset.live = c.available ? '1' : '';
  if (!c.available) { el.textContent = c.reason; return; }
  let text = `library scene ${c.name} (reference ${c.reference_samples} spp)`;
  if (c.differs.length) text += `\nnot as the reference was made: ${c.differs.join(', ')}`;
  if (c.relmse !== undefined && c.expected_relmse !== undefined) {
    const ok = c.relmse <= c.bound_relmse;
    text += `\nrelMSE ${fmt(c.relmse)} at ${fmt(c.spp)} spp; a correct render: ${fmt(c.expected_relmse)} ± ${fmt(c.sd_relmse, 2)}` +
      ` (bound ${fmt(c.bound_relmse)}) → ${ok ? 'within what the spp explains' : 'MORE than noise explains'}`;
  }
  el.textContent = text;
}

// ---- BVH walk ----------------------------------------------------------------
async function walk(path) {
  const r = await act(api('GET', '/api/bvh?path=' + encodeURIComponent(path)));
  if (!r) return;
  view.bvhPath = path;
  view.bvh = r.data;
  const b = r.data, s = b.sah;
  $('bvh-info').innerHTML = `node <b>${path || '(root)'}</b> · depth ${b.depth} · ${b.count} primitives` +
    `${b.leaf ? ' · leaf' : ''}<br>SAH: leaf cost ${fmt(s.leaf_cost)}, split cost ${s.split_cost === undefined ? '—' : fmt(s.split_cost)}` +
    `, subtree cost ${fmt(s.subtree_cost)}<br>box min ${b.bbox.min.map((v) => fmt(v)).join(', ')} max ${b.bbox.max.map((v) => fmt(v)).join(', ')}` +
    (b.primitives_drawn < b.count ? `<br>drawn: ${b.primitives_drawn} of ${b.count}` : '');
  draw();
}
$('bvh-root').onclick = () => walk('');
$('bvh-left').onclick = () => walk(view.bvhPath + 'l');
$('bvh-right').onclick = () => walk(view.bvhPath + 'r');
$('bvh-parent').onclick = () => walk(view.bvhPath.slice(0, -1));
// The keys, except while typing in a field: a radio button or a button just
// clicked keeps the focus, and the keys must work then too.
function typing(el) {
  return el.tagName === 'TEXTAREA' || el.tagName === 'SELECT' ||
    (el.tagName === 'INPUT' && !['radio', 'checkbox', 'button'].includes(el.type));
}
document.addEventListener('keydown', (e) => {
  if (typing(e.target) || e.ctrlKey || e.metaKey || e.altKey) return;
  const k = e.key.toLowerCase();
  if (k === 'f') flip();
  if (view.mode !== 'bvh') return;
  if (k === 'l') walk(view.bvhPath + 'l');
  if (k === 'r') walk(view.bvhPath + 'r');
  if (k === 'p') walk(view.bvhPath.slice(0, -1));
  if (k === 't') walk('');
});

// ---- pixel inspector ---------------------------------------------------------
function v3(a) { return a ? a.map((x) => fmt(x)).join(', ') : ''; }
function badCell(a) { return a && a.some((x) => x === null || x < 0) ? ' class="bad"' : ''; }

async function inspect(x, y) {
  const r = await act(api('GET', `/api/pixel?x=${x}&y=${y}`));
  if (!r) return;
  const p = (view.path = r.data);
  let html = `pixel (${x}, ${y}) from the top-left: value <span${badCell(p.value)}>${v3(p.value)}</span>, ${p.samples} samples<br>`;
  html += 'One path, traced by the viewer calling your task functions in turn:<table><tr><th>#</th><th>hit</th><th>direct light (P3T5) and light samples</th><th>BSDF sample</th><th>RR</th></tr>';
  for (const v of p.vertices) {
    if (v.escaped) { html += `<tr><td>${v.index}</td><td colspan="4">escaped: background ${v3(v.background)}</td></tr>`; continue; }
    const b = v.bsdf_sample, rr = v.russian_roulette;
    const lights = (v.light_samples || []).map((l) => `light ${l.light}: pdf ${fmt(l.pdf)}, L ${v3(l.radiance)}, ${l.visible ? 'visible' : 'shadowed'}`).join('<br>');
    html += `<tr><td>${v.index}</td><td>${v.primitive_kind} #${v.primitive}<br>p ${v3(v.point)}<br>n ${v3(v.normal)}` +
      `${v.emitted ? '<br>Le ' + v3(v.emitted) : ''}${v.error ? '<br><span class="bad">' + v.error + '</span>' : ''}</td>` +
      `<td><span${badCell(v.direct)}>${v3(v.direct)}</span><br>${lights}</td>` +
      `<td>${b ? `wi ${v3(b.direction)}<br>f <span${badCell(b.f)}>${v3(b.f)}</span><br>pdf <span${badCell([b.pdf])}>${fmt(b.pdf)}</span>` : v.end || ''}</td>` +
      `<td>${rr ? `p ${fmt(rr.p)}, draw ${fmt(rr.draw)}: ${rr.survives ? 'continues' : 'ends'}` : ''}</td></tr>`;
  }
  html += '</table>';
  if (p.error) html += `<div class="bad">${p.error}</div>`;
  for (const w of p.warnings) html += `<div class="bad">${w}</div>`;
  $('pixel-info').innerHTML = html;
  draw();
}

// ---- mouse: camera, cell, BVH, inspector --------------------------------------
const sub = (a, b) => a.map((x, i) => x - b[i]);
const add = (a, b) => a.map((x, i) => x + b[i]);
const mul = (a, s) => a.map((x) => x * s);
const dot = (a, b) => a.reduce((s, x, i) => s + x * b[i], 0);
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => mul(a, 1 / Math.hypot(...a));
// Rodrigues: v rotated by angle about the unit axis k.
const rotate = (v, k, angle) =>
  add(add(mul(v, Math.cos(angle)), mul(cross(k, v), Math.sin(angle))), mul(k, dot(k, v) * (1 - Math.cos(angle))));

function imagePoint(e) {
  const r = canvas.getBoundingClientRect();
  const w = view.image ? view.image.width : canvas.width, h = view.image ? view.image.height : canvas.height;
  return [Math.floor((e.clientX - r.left) / r.width * w), Math.floor((e.clientY - r.top) / r.height * h)];
}

// The course viewer's controls: orbit about the target around the up axis,
// pan in the image plane, zoom towards the target.
function moveCamera(cam, dx, dy, pan) {
  const up = norm(cam.up), offset = sub(cam.position, cam.target);
  if (pan) {
    const dist = Math.hypot(...offset), forward = mul(offset, -1 / dist), right = norm(cross(forward, up));
    const camUp = cross(right, forward), perPixel = 2 * dist * Math.tan(cam.vfov * Math.PI / 360) / canvas.clientHeight;
    const shift = add(mul(right, -dx * perPixel), mul(camUp, dy * perPixel));
    return { ...cam, position: add(cam.position, shift), target: add(cam.target, shift) };
  }
  let o = rotate(offset, up, -dx * 0.01);
  const right = norm(cross(up, o)), pitched = rotate(o, right, dy * 0.01);
  if (Math.abs(dot(norm(pitched), up)) < 0.99) o = pitched;  // never look straight along the up axis
  return { ...cam, position: add(cam.target, o) };
}

let lastSent = 0;
function sendCamera(cam, force) {
  const now = performance.now();
  if (!force && now - lastSent < 120) return;
  lastSent = now;
  view.status.camera = cam;
  view.shownVersion = -1;
  act(api('POST', '/api/camera', cam));
}

canvas.addEventListener('contextmenu', (e) => e.preventDefault());
canvas.addEventListener('mousedown', (e) => {
  if (!view.status) return;
  view.drag = { x: e.clientX, y: e.clientY, start: imagePoint(e), cam: view.status.camera, pan: e.shiftKey || e.button === 2, moved: false };
});
window.addEventListener('mousemove', (e) => {
  const d = view.drag;
  if (!d) return;
  const dx = e.clientX - d.x, dy = e.clientY - d.y;
  if (Math.abs(dx) + Math.abs(dy) > 2) d.moved = true;
  if (view.mode === 'camera' && d.moved) sendCamera(moveCamera(d.cam, dx, dy, d.pan), false);
  if (view.mode === 'cell') {
    const [x, y] = imagePoint(e), [x0, y0] = d.start;
    d.rect = [Math.min(x, x0), Math.min(y, y0), Math.max(x, x0) + 1, Math.max(y, y0) + 1];
    draw();
  }
});
window.addEventListener('mouseup', (e) => {
  const d = view.drag;
  view.drag = null;
  if (!d) return;
  const dx = e.clientX - d.x, dy = e.clientY - d.y;
  if (view.mode === 'camera' && d.moved) sendCamera(moveCamera(d.cam, dx, dy, d.pan), true);
  if (view.mode === 'cell' && d.rect) {
    const c = d.rect.map((v, i) => Math.max(0, Math.min(v, i % 2 ? view.image.height : view.image.width)));
    act(api('POST', '/api/cell', c));
  }
  if (view.mode === 'inspect' && !d.moved) inspect(...d.start);
});
canvas.addEventListener('dblclick', () => { if (view.mode === 'cell') act(api('POST', '/api/cell', null)); });
canvas.addEventListener('wheel', (e) => {
  e.preventDefault();
  if (!view.status || view.mode !== 'camera') return;
  const cam = view.status.camera, offset = mul(sub(cam.position, cam.target), Math.exp(e.deltaY * 0.001));
  sendCamera({ ...cam, position: add(cam.target, offset) }, false);
}, { passive: false });

document.querySelectorAll('input[name=mode]').forEach((el) => el.addEventListener('change', () => {
  view.mode = el.value;
  $('help').textContent = helpText[view.mode];
  if (view.mode === 'bvh' && !view.bvh) walk('');
  draw();
}));

// Closing the page stops the render (a reload starts it again).
window.addEventListener('pagehide', () => navigator.sendBeacon('/api/control?action=stop'));
$('help').textContent = helpText.camera;
poll();
