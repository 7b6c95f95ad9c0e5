// fedsim instructor station page. The server (fedsim-ios) pushes the whole live picture on the
// WebSocket /ws several times a second; the page keeps short histories for the map track and
// the plots, draws on canvases at the display's rate, and sends commands with POST /api/command.
// A command is shown "confirmed" only when the station saw the federation do it.
'use strict';

const KT_PER_MPS = 3600 / 1852;
const FT_PER_M = 1 / 0.3048;
const DEG = 180 / Math.PI;
const NM_M = 1852;

// Everything a test (or a curious user in the console) may look at.
const fedsim = window.fedsim = {
  state: null,            // the newest push
  pushes: 0,              // pushes received
  track: [],              // [{lat, lon}] aircraft positions (deg)
  plot: { series: [], paused: false, windowS: 30 },
  stats: { frames: 0, fps: 0, pushHz: 0 },
  map: null,              // the airport's runways, ILS and navaids
  view: { lat: 37.62, lon: -122.37, pxPerNm: 22 },
};

const token = new URLSearchParams(location.search).get('token');
if (token) document.cookie = 'fedsim_token=' + encodeURIComponent(token) + '; SameSite=Strict';

const $ = (id) => document.getElementById(id);

// ---- live data ----

function connect() {
  const ws = new WebSocket((location.protocol === 'https:' ? 'wss://' : 'ws://') + location.host + '/ws');
  ws.onopen = () => setBadge($('link'), 'live', 'good');
  ws.onclose = () => { setBadge($('link'), 'disconnected', 'bad'); setTimeout(connect, 1000); };
  ws.onmessage = (event) => onState(JSON.parse(event.data));
}

function field(topic, name) {
  const t = fedsim.state && fedsim.state.topics[topic];
  if (!t || !(name in t.f)) return undefined;
  return t.f[name];
}

const pushTimes = [];
function onState(s) {
  fedsim.state = s;
  fedsim.pushes++;
  const now = performance.now();
  pushTimes.push(now);
  while (pushTimes.length > 0 && now - pushTimes[0] > 2000) pushTimes.shift();
  fedsim.stats.pushHz = pushTimes.length / 2;
  const lat = field('fedsim/aircraft_state', 'latitude_rad');
  const lon = field('fedsim/aircraft_state', 'longitude_rad');
  if (lat !== undefined && lat !== null) {
    const p = { lat: lat * DEG, lon: lon * DEG };
    const last = fedsim.track[fedsim.track.length - 1];
    if (!last || last.lat !== p.lat || last.lon !== p.lon) fedsim.track.push(p);
    if (fedsim.track.length > 5000) fedsim.track.shift();
    if ($('map-follow').checked) { fedsim.view.lat = p.lat; fedsim.view.lon = p.lon; }
  }
  sampleplots(s);
  updateTables(s);
  updatePlotChoices(s);
  updatePicture(s);
  updateReplay(s);
  updateScenario(s);
}

// ---- header and tables ----

function setBadge(el, text, kind) { el.textContent = text; el.className = 'badge ' + (kind || ''); }

function updateTables(s) {
  const t = s.timing || {};
  setBadge($('runstate'), (t.run_state || '-').toUpperCase(),
           t.run_state === 'run' ? 'good' : t.run_state === 'freeze' ? 'warn' : '');
  $('simtime').textContent = 't = ' + (t.sim_time_s !== undefined ? t.sim_time_s.toFixed(2) + ' s' : '-');
  $('mode').textContent = (t.mode || '-') + (t.rate_hz ? ' ' + t.rate_hz.toFixed(0) + ' Hz' : '') +
                          (t.frame !== undefined ? ', frame ' + t.frame : '');
  $('federates').tBodies[0].innerHTML = s.federates.map((f) =>
    `<tr><td>${esc(f.name)}</td><td class="state-${f.state}" title="${esc(f.message)}">${f.state}</td>` +
    `<td class="num">${f.frames}</td><td class="num">${f.compute_mean_us.toFixed(0)} / ${f.compute_max_us.toFixed(0)}</td>` +
    `<td class="num">${f.overruns}</td><td class="num">${f.late_inputs}</td><td class="num">${f.faults}</td></tr>`).join('');
  $('settings').innerHTML = Object.entries(s.settings).map(([k, v]) => `<li><b>${esc(k)}</b>: ${esc(v)}</li>`).join('');
  $('commands').tBodies[0].innerHTML = s.commands.slice(0, 12).map((c) =>
    `<tr><td>${c.sequence}</td><td>${esc(c.text)}</td><td class="status-${c.status}">${c.status}</td>` +
    `<td>${esc(c.evidence)}</td></tr>`).join('');
}

function esc(text) {
  return String(text).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' }[c]));
}

// ---- commands ----

async function sendCommand(body) {
  $('command-error').textContent = '';
  const response = await fetch('api/command', { method: 'POST', body: JSON.stringify(body),
                                                headers: { 'Content-Type': 'application/json' } });
  const reply = await response.json();
  if (!response.ok) $('command-error').textContent = reply.error || ('HTTP ' + response.status);
  return reply;
}
fedsim.sendCommand = sendCommand;

function formNumbers(form, names) {
  const out = {};
  for (const n of names) {
    const v = form.elements[n].value.trim();
    if (v !== '') out[n] = Number(v);  // the server refuses what is not a number, by name
  }
  return out;
}

function wireForms() {
  for (const b of document.querySelectorAll('#runbar button')) {
    b.onclick = () => sendCommand({ command: b.dataset.command });
  }
  $('form-runway').onsubmit = (e) => {
    e.preventDefault();
    const f = e.target;
    sendCommand({ command: 'reposition', airport: f.airport.value.trim().toUpperCase(),
                  runway: f.runway.value.trim().toUpperCase(), ...formNumbers(f, ['gate_nm']) });
  };
  $('form-point').onsubmit = (e) => {
    e.preventDefault();
    sendCommand({ command: 'reposition', ...formNumbers(e.target, ['lat_deg', 'lon_deg', 'alt_ft', 'heading_deg', 'kt']) });
  };
  $('form-weather').onsubmit = (e) => {
    e.preventDefault();
    const f = e.target;
    sendCommand({ command: 'weather', turbulence: f.turbulence.value,
                  ...formNumbers(f, ['wind_from_deg', 'wind_kt', 'gradient_kt_per_1000ft', 'visibility_m',
                                     'cloud_base_ft', 'isa_dev_k', 'qnh_hpa']) });
  };
  $('form-failure').onsubmit = (e) => {
    e.preventDefault();
    const restore = e.submitter && e.submitter.name === 'restore';
    sendCommand({ command: restore ? 'restore' : 'fail', system: e.target.system.value });
  };
  $('form-time').onsubmit = (e) => {
    e.preventDefault();
    sendCommand({ command: 'time_of_day', utc: e.target.utc.value.trim(), lights: e.target.lights.checked });
  };
}

// ---- scenarios (seed 9.8) ----

let scenarioFiles = '';
function updateScenario(s) {
  const sc = s.scenario;
  if (!sc) return;
  const files = sc.files.join(',');
  if (files !== scenarioFiles) {
    scenarioFiles = files;
    $('form-scenario').elements.name.innerHTML = sc.files.map((f) => `<option>${esc(f)}</option>`).join('');
  }
  $('scenario-status').textContent = sc.running ? `running ${sc.name}` + (sc.waiting_for && sc.waiting_for.length ?
    `; waiting for ${sc.waiting_for.join(', ')}` : '') : (sc.name ? `${sc.name} ended` : 'none running');
  $('scenario-fired').innerHTML = (sc.fired || []).map((f) => `<li>${esc(f)}</li>`).join('');
}

function wireScenario() {
  $('form-scenario').onsubmit = async (e) => {
    e.preventDefault();
    const stop = e.submitter && e.submitter.name === 'stop';
    $('command-error').textContent = '';
    const response = await fetch('api/scenario', { method: 'POST',
      body: JSON.stringify(stop ? { action: 'stop' } : { action: 'start', name: e.target.elements.name.value }) });
    const reply = await response.json();
    if (!response.ok) $('command-error').textContent = reply.error;
  };
}

// ---- replay (seed 9.7) ----

async function replayRequest(body) {
  $('command-error').textContent = '';
  const response = await fetch('api/replay', { method: 'POST', body: JSON.stringify(body) });
  const reply = await response.json();
  if (!response.ok) $('command-error').textContent = reply.error || ('HTTP ' + response.status);
  return reply;
}
fedsim.replayRequest = replayRequest;

async function loadRecordings() {
  const names = await (await fetch('api/recordings')).json();
  $('replay-recording').innerHTML = '<option value="">(a recording)</option>' +
    names.map((n) => `<option>${esc(n)}</option>`).join('');
}

function updateReplay(s) {
  const r = s.replay;
  if (!r) return;
  const seek = $('replay-seek');
  if (r.active) {
    seek.disabled = false;
    seek.max = r.length_s.toFixed(1);
    if (document.activeElement !== seek) seek.value = r.position_s.toFixed(1);
    $('replay-pause').textContent = r.playing ? 'Pause' : 'Resume';
    $('replay-status').innerHTML = `<span class="badge warn">REPLAY</span> ${esc(r.source)}: ` +
      `${r.position_s.toFixed(1)} / ${r.length_s.toFixed(1)} s at ${r.speed}x${r.playing ? '' : ', paused'}` +
      `${r.finished ? ', at the end (take control to fly on)' : ''}`;
  } else {
    seek.disabled = true;
    $('replay-pause').textContent = 'Pause';
    $('replay-status').textContent = `live; ${r.ring_s.toFixed(0)} s of live state held for replay`;
  }
}

function wireReplay() {
  $('replay-ring').onclick = () => replayRequest({ action: 'start', source: 'ring', last_s: Number($('replay-last').value),
                                                   speed: Number($('replay-speed').value) });
  $('replay-recording-start').onclick = () => {
    const name = $('replay-recording').value;
    if (name) replayRequest({ action: 'start', source: 'recording', name, speed: Number($('replay-speed').value) });
  };
  $('replay-pause').onclick = () => {
    const r = fedsim.state && fedsim.state.replay;
    replayRequest({ action: r && r.playing ? 'pause' : 'resume' });
  };
  $('replay-speed').onchange = () => {
    if (fedsim.state && fedsim.state.replay && fedsim.state.replay.active) {
      replayRequest({ action: 'speed', speed: Number($('replay-speed').value) });
    }
  };
  $('replay-seek').onchange = () => replayRequest({ action: 'seek', t_s: Number($('replay-seek').value) });
  $('replay-take').onclick = () => replayRequest({ action: 'take_control' });
  loadRecordings();
}

// ---- map (seed 9.6): equirectangular about the view centre, north up ----

async function loadMap(airport) {
  const response = await fetch('api/map' + (airport ? '?airport=' + encodeURIComponent(airport) : ''));
  const map = await response.json();
  if (!response.ok) { $('map-info').textContent = map.error; return; }
  fedsim.map = map;
  $('map-airport').value = map.airport;
  $('map-info').textContent = `${map.airport}: ${map.runways.length} runway ends, ${map.ils.length} ILS, ${map.navaids.length} navaids`;
  if (!fedsim.track.length) { fedsim.view.lat = map.center.lat_deg; fedsim.view.lon = map.center.lon_deg; }
}

function project(lat, lon) {
  const c = $('map');
  const v = fedsim.view;
  const x = (lon - v.lon) * 60 * Math.cos(v.lat / DEG) * v.pxPerNm + c.width / 2;
  const y = -(lat - v.lat) * 60 * v.pxPerNm + c.height / 2;
  return [x, y];
}

function unproject(x, y) {
  const c = $('map');
  const v = fedsim.view;
  return { lat: v.lat - (y - c.height / 2) / (60 * v.pxPerNm),
           lon: v.lon + (x - c.width / 2) / (60 * Math.cos(v.lat / DEG) * v.pxPerNm) };
}

// A point `nm` from (lat, lon) on a true bearing (flat-earth: the map's own projection).
function offset(lat, lon, bearingDeg, nm) {
  const b = bearingDeg / DEG;
  return { lat: lat + nm * Math.cos(b) / 60, lon: lon + nm * Math.sin(b) / (60 * Math.cos(lat / DEG)) };
}

function drawMap() {
  const c = $('map');
  const g = c.getContext('2d');
  g.fillStyle = '#0b1a24';
  g.fillRect(0, 0, c.width, c.height);
  const v = fedsim.view;
  // Range rings every 5 NM about the aircraft (or the view centre).
  const ac = fedsim.track[fedsim.track.length - 1] || { lat: v.lat, lon: v.lon };
  const [ax, ay] = project(ac.lat, ac.lon);
  g.strokeStyle = '#1f3546';
  g.fillStyle = '#3d5d75';
  g.font = '10px sans-serif';
  for (let r = 5; r <= 40; r += 5) {
    g.beginPath();
    g.arc(ax, ay, r * v.pxPerNm, 0, 2 * Math.PI);
    g.stroke();
    g.fillText(r + ' NM', ax + r * v.pxPerNm * 0.707 + 2, ay - r * v.pxPerNm * 0.707);
  }
  const m = fedsim.map;
  if (m) {
    // ILS feathers: the localizer sector out to 10 NM from the threshold.
    m.ils.forEach((ils, k) => {
      const back = (ils.course_deg + 180) % 360;
      const t = ils.threshold;
      const l = offset(t.lat_deg, t.lon_deg, back - ils.half_width_deg, 10);
      const r = offset(t.lat_deg, t.lon_deg, back + ils.half_width_deg, 10);
      const centre = offset(t.lat_deg, t.lon_deg, back, 12);
      g.fillStyle = 'rgba(90, 160, 255, 0.13)';
      g.strokeStyle = 'rgba(120, 180, 255, 0.7)';
      g.beginPath();
      g.moveTo(...project(t.lat_deg, t.lon_deg));
      g.lineTo(...project(l.lat, l.lon));
      g.lineTo(...project(centre.lat, centre.lon));
      g.lineTo(...project(r.lat, r.lon));
      g.closePath();
      g.fill();
      g.stroke();
      const [lx, ly] = project(centre.lat, centre.lon);
      g.fillStyle = '#8fc0ff';
      g.fillText(`${ils.runway} ${ils.ident} ${ils.mhz.toFixed(2)}`, lx + 3, ly + 12 * k);  // parallel runways: one line each
    });
    // Runways: threshold to the far end, at least 3 px wide.
    g.strokeStyle = '#e8e8e8';
    for (const r of m.runways) {
      g.lineWidth = Math.max(3, r.width_m / NM_M * v.pxPerNm);
      g.beginPath();
      g.moveTo(...project(r.lat_deg, r.lon_deg));
      g.lineTo(...project(r.end_lat_deg, r.end_lon_deg));
      g.stroke();
    }
    g.lineWidth = 1;
    for (const n of m.navaids) {
      const [x, y] = project(n.lat_deg, n.lon_deg);
      g.strokeStyle = n.type.startsWith('NDB') ? '#c98bff' : '#58d0c0';
      g.beginPath();
      g.arc(x, y, 5, 0, 2 * Math.PI);
      g.stroke();
      g.fillStyle = g.strokeStyle;
      g.fillText(n.ident, x + 7, y + 3);
    }
  }
  // Track and aircraft.
  g.strokeStyle = '#f0c040';
  g.beginPath();
  fedsim.track.forEach((p, i) => { const [x, y] = project(p.lat, p.lon); i ? g.lineTo(x, y) : g.moveTo(x, y); });
  g.stroke();
  const psi = field('fedsim/aircraft_state', 'psi_rad');
  if (fedsim.track.length && psi !== undefined) {
    g.save();
    g.translate(ax, ay);
    g.rotate(psi);
    g.fillStyle = '#ffd24a';
    g.beginPath();
    g.moveTo(0, -10); g.lineTo(7, 8); g.lineTo(0, 4); g.lineTo(-7, 8);
    g.closePath();
    g.fill();
    g.restore();
  }
  g.fillStyle = '#8aa2b8';
  g.fillText(`${v.lat.toFixed(4)} ${v.lon.toFixed(4)}  ${(c.width / v.pxPerNm).toFixed(1)} NM across`, 6, c.height - 6);
}

function wireMap() {
  const c = $('map');
  let drag = null;
  c.onmousedown = (e) => { drag = { x: e.offsetX, y: e.offsetY, moved: false }; };
  c.onmousemove = (e) => {
    if (!drag) return;
    const sx = c.width / c.clientWidth;
    const dx = (e.offsetX - drag.x) * sx, dy = (e.offsetY - drag.y) * sx;
    if (Math.abs(dx) + Math.abs(dy) > 3) {
      drag.moved = true;
      $('map-follow').checked = false;
      const p = unproject(c.width / 2 - dx, c.height / 2 - dy);
      fedsim.view.lat = p.lat;
      fedsim.view.lon = p.lon;
      drag.x = e.offsetX;
      drag.y = e.offsetY;
    }
  };
  c.onmouseup = (e) => {
    if (drag && !drag.moved) mapClick(e.offsetX * c.width / c.clientWidth, e.offsetY * c.height / c.clientHeight);
    drag = null;
  };
  c.onwheel = (e) => {
    e.preventDefault();
    fedsim.view.pxPerNm = Math.min(400, Math.max(0.5, fedsim.view.pxPerNm * (e.deltaY < 0 ? 1.25 : 0.8)));
  };
  $('map-load').onclick = () => loadMap($('map-airport').value.trim().toUpperCase());
  $('map-centre').onclick = () => { $('map-follow').checked = true; };
}

// A click on the map: the point form takes the place; with "click repositions" on, the aircraft
// is moved there at its present altitude, heading and speed.
function mapClick(x, y) {
  const p = unproject(x, y);
  const f = $('form-point');
  f.lat_deg.value = p.lat.toFixed(5);
  f.lon_deg.value = p.lon.toFixed(5);
  const alt = field('fedsim/aircraft_state', 'altitude_msl_m');
  const psi = field('fedsim/aircraft_state', 'psi_rad');
  if (alt !== undefined) f.alt_ft.value = Math.round(alt * FT_PER_M);
  if (psi !== undefined) f.heading_deg.value = Math.round(((psi * DEG) % 360 + 360) % 360);
  if ($('map-click-moves').checked) f.requestSubmit();
}
fedsim.mapClick = mapClick;

// ---- instruments: a PFD-lite drawn from the aircraft state ----

function drawPfd() {
  const c = $('pfd');
  const g = c.getContext('2d');
  const W = c.width, H = c.height;
  g.fillStyle = '#000';
  g.fillRect(0, 0, W, H);
  const a = (n) => field('fedsim/aircraft_state', n);
  const theta = a('theta_rad'), phi = a('phi_rad');
  if (theta === undefined || theta === null) {
    g.fillStyle = '#888';
    g.fillText('no aircraft state', W / 2 - 40, H / 2);
    return;
  }
  const cx = W / 2, cy = H / 2 - 10, pxPerDeg = 4;
  // Attitude: sky and ground about the horizon, rotated by roll, moved by pitch.
  g.save();
  g.beginPath();
  g.rect(70, 20, W - 140, H - 70);
  g.clip();
  g.translate(cx, cy);
  g.rotate(-phi);
  g.translate(0, theta * DEG * pxPerDeg);
  g.fillStyle = '#2f6fb3';
  g.fillRect(-400, -800, 800, 800);
  g.fillStyle = '#7a5230';
  g.fillRect(-400, 0, 800, 800);
  g.strokeStyle = '#fff';
  g.fillStyle = '#fff';
  g.font = '10px sans-serif';
  for (let p = -30; p <= 30; p += 5) {
    const y = -p * pxPerDeg;
    const w = p === 0 ? 300 : p % 10 === 0 ? 40 : 20;
    g.beginPath();
    g.moveTo(-w, y);
    g.lineTo(w, y);
    g.stroke();
    if (p !== 0 && p % 10 === 0) g.fillText(String(Math.abs(p)), w + 3, y + 3);
  }
  g.restore();
  // The aircraft symbol.
  g.strokeStyle = '#ffd24a';
  g.lineWidth = 3;
  g.beginPath();
  g.moveTo(cx - 50, cy); g.lineTo(cx - 15, cy); g.lineTo(cx - 15, cy + 8);
  g.moveTo(cx + 50, cy); g.lineTo(cx + 15, cy); g.lineTo(cx + 15, cy + 8);
  g.stroke();
  g.lineWidth = 1;
  // Speed (left), altitude (right), heading (bottom), vertical speed.
  const cas = a('air.cas_mps'), alt = a('altitude_msl_m'), psi = a('psi_rad'), vs = a('climb_rate_mps');
  g.fillStyle = '#fff';
  g.font = 'bold 16px sans-serif';
  g.fillText(cas !== undefined ? (cas * KT_PER_MPS).toFixed(0) : '---', 12, cy + 6);
  g.fillText(alt !== undefined ? (alt * FT_PER_M).toFixed(0) : '---', W - 64, cy + 6);
  g.font = '11px sans-serif';
  g.fillText('KCAS', 18, cy + 22);
  g.fillText('FT', W - 50, cy + 22);
  g.fillText(vs !== undefined ? 'VS ' + (vs * FT_PER_M * 60).toFixed(0) + ' fpm' : '', W - 90, cy + 60);
  g.font = 'bold 15px sans-serif';
  const hdg = psi !== undefined ? ((psi * DEG % 360) + 360) % 360 : undefined;
  g.fillText(hdg !== undefined ? 'HDG ' + hdg.toFixed(0).padStart(3, '0') : '', cx - 34, H - 12);
  const fma = fedsim.state.topics['fedsim/autopilot_state'];
  if (fma) {
    g.font = '11px sans-serif';
    g.fillStyle = '#5fd38d';
    g.fillText(`FMA thrust ${fma.f['fma.thrust_mode']}  roll ${fma.f['fma.roll_mode']}  pitch ${fma.f['fma.pitch_mode']}`, 8, 14);
  }
}

// ---- the visual channel's live picture ----

let pictureCount = -1;
function updatePicture(s) {
  const p = s.pictures[0];
  if (!p || p.count === pictureCount) return;
  pictureCount = p.count;
  $('channel').src = 'api/picture?channel=' + p.channel_id + '&n=' + p.count;
  $('channel-info').textContent = `channel ${p.name}: ${p.width}x${p.height}, frame ${p.frame}, picture ${p.count}`;
}

// ---- plots: strip charts of any numeric field of any topic ----

const PLOT_COLOURS = ['#ffd24a', '#5fd38d', '#58b0ff', '#ff7b7b', '#c98bff', '#4fe0d0'];
let knownTopics = '';

function updatePlotChoices(s) {
  const topics = Object.keys(s.topics).sort();
  const key = topics.join(',');
  if (key === knownTopics) return;
  knownTopics = key;
  const sel = $('plot-topic');
  const current = sel.value;
  sel.innerHTML = topics.map((t) => `<option>${esc(t)}</option>`).join('');
  sel.value = topics.includes(current) ? current : (topics.includes('fedsim/aircraft_state') ? 'fedsim/aircraft_state' : topics[0]);
  fillFields();
}

function fillFields() {
  const t = fedsim.state && fedsim.state.topics[$('plot-topic').value];
  const sel = $('plot-field');
  const current = sel.value;
  const names = t ? Object.keys(t.f) : [];
  sel.innerHTML = names.map((n) => `<option>${esc(n)}</option>`).join('');
  if (names.includes(current)) sel.value = current;
  else if (names.includes('altitude_msl_m')) sel.value = 'altitude_msl_m';
}

function addSeries(topic, name) {
  if (fedsim.plot.series.some((s) => s.topic === topic && s.field === name)) return;
  fedsim.plot.series.push({ topic, field: name, points: [], colour: PLOT_COLOURS[fedsim.plot.series.length % PLOT_COLOURS.length] });
}
fedsim.addSeries = addSeries;

function sampleplots(s) {
  const t = s.wall_s;
  for (const series of fedsim.plot.series) {
    const v = field(series.topic, series.field);
    if (v === undefined || v === null) continue;
    series.points.push([t, v]);
    while (series.points.length && t - series.points[0][0] > 600) series.points.shift();
  }
}

function drawPlot() {
  const c = $('plot');
  const g = c.getContext('2d');
  g.fillStyle = '#0b0f14';
  g.fillRect(0, 0, c.width, c.height);
  if (!fedsim.plot.paused) fedsim.plot.now = fedsim.state ? fedsim.state.wall_s : 0;
  const tEnd = fedsim.plot.now || 0, span = fedsim.plot.windowS, tStart = tEnd - span;
  const left = 60, right = c.width - 8, top = 8, bottom = c.height - 20;
  g.strokeStyle = '#26313b';
  g.fillStyle = '#7d8d9c';
  g.font = '10px sans-serif';
  for (let i = 0; i <= 5; i++) {
    const x = left + (right - left) * i / 5;
    g.beginPath(); g.moveTo(x, top); g.lineTo(x, bottom); g.stroke();
    g.fillText('-' + (span * (5 - i) / 5).toFixed(0) + ' s', x - 12, c.height - 6);
  }
  const legend = [];
  fedsim.plot.series.forEach((s, k) => {
    const pts = s.points.filter((p) => p[0] >= tStart && p[0] <= tEnd);
    if (!pts.length) { legend.push(`<span style="color:${s.colour}">${esc(s.topic)} ${esc(s.field)}: -</span>`); return; }
    let lo = Math.min(...pts.map((p) => p[1])), hi = Math.max(...pts.map((p) => p[1]));
    if (hi - lo < 1e-9) { lo -= 1; hi += 1; }
    // Each series on its own scale, stated in the legend.
    g.strokeStyle = s.colour;
    g.beginPath();
    pts.forEach((p, i) => {
      const x = left + (p[0] - tStart) / span * (right - left);
      const y = bottom - (p[1] - lo) / (hi - lo) * (bottom - top);
      i ? g.lineTo(x, y) : g.moveTo(x, y);
    });
    g.stroke();
    g.fillStyle = s.colour;
    g.fillText(hi.toPrecision(5), 2, top + 10 + k * 11);
    legend.push(`<span style="color:${s.colour}">${esc(s.topic)} ${esc(s.field)}: ${pts[pts.length - 1][1].toPrecision(6)} ` +
                `(${lo.toPrecision(4)}..${hi.toPrecision(4)})</span>`);
  });
  $('plot-legend').innerHTML = legend.join('<br>');
}

function wirePlots() {
  $('plot-topic').onchange = fillFields;
  $('plot-add').onclick = () => addSeries($('plot-topic').value, $('plot-field').value);
  $('plot-clear').onclick = () => { fedsim.plot.series = []; };
  $('plot-pause').onclick = () => {
    fedsim.plot.paused = !fedsim.plot.paused;
    $('plot-pause').textContent = fedsim.plot.paused ? 'Resume' : 'Pause';
  };
  $('plot-window').onchange = () => { fedsim.plot.windowS = Number($('plot-window').value); };
}

// ---- the page's own frame rate ----

const frameTimes = [];
function frame(now) {
  frameTimes.push(now);
  while (frameTimes.length && now - frameTimes[0] > 1000) frameTimes.shift();
  fedsim.stats.frames++;
  fedsim.stats.fps = frameTimes.length;
  if (fedsim.state) {
    drawMap();
    drawPfd();
    drawPlot();
  }
  $('pagestats').textContent = `page ${fedsim.stats.fps} fps, ${fedsim.stats.pushHz.toFixed(1)} pushes/s` +
    (fedsim.state ? `, server ${fedsim.state.server.push_hz_measured.toFixed(1)}/s to ${fedsim.state.server.clients} page(s)` : '');
  requestAnimationFrame(frame);
}

wireForms();
wireScenario();
wireReplay();
wireMap();
wirePlots();
addSeries('fedsim/aircraft_state', 'altitude_msl_m');
addSeries('fedsim/aircraft_state', 'air.cas_mps');
fetch('api/config').then((r) => r.json()).then((cfg) => loadMap(cfg.airport));
connect();
requestAnimationFrame(frame);
