// The clips play page: talks to the JSON API of `clips serve` (docs/api.md).
// Plain JS, no libraries, nothing fetched from outside the server.
'use strict';

const COLOURS = { red: '#d62728', yellow: '#e6b800', blue: '#1f77b4', green: '#2ca02c', pink: '#e377c2',
                  orange: '#ff7f0e', purple: '#9467bd', '': '#888' };
const SERIES = ['#d62728', '#1f77b4', '#2ca02c', '#e6b800', '#9467bd', '#8c564b', '#e377c2', '#17becf', '#7f7f7f'];
const $ = (id) => document.getElementById(id);

const ui = { catalogue: null, session: null, state: null, busy: false };
window.clips = ui;  // for tests and the curious

async function api(method, path, body) {
  const res = await fetch(path, {
    method, headers: body ? { 'Content-Type': 'application/json' } : {},
    body: body ? JSON.stringify(body) : undefined,
  });
  const data = await res.json();
  if (!res.ok) throw new Error(data.error || ('HTTP ' + res.status));
  return data;
}

function log(text, cls) {
  const li = document.createElement('li');
  li.textContent = text;
  if (cls) li.className = cls;
  $('log').appendChild(li);
  $('log').scrollTop = $('log').scrollHeight;
}

function fillSelect(sel, items, label) {
  sel.innerHTML = '';
  for (const it of items) {
    const o = document.createElement('option');
    o.value = it; o.textContent = label ? label(it) : it;
    sel.appendChild(o);
  }
}

function currentDataset() { return ui.catalogue.datasets.find((d) => d.name === $('dataset').value); }
function onDataset() {
  const ds = currentDataset();
  fillSelect($('problem'), ds ? ds.problems.map((p) => p.id) : []);
  onProblem();
}
function onProblem() {
  const ds = currentDataset();
  const p = ds && ds.problems.find((q) => q.id === $('problem').value);
  fillSelect($('plan'), p ? p.plans : []);
}

async function loadCatalogue() {
  ui.catalogue = await api('GET', '/api/datasets');
  fillSelect($('dataset'), ui.catalogue.datasets.map((d) => d.name));
  onDataset();
}

// Runs one request at a time; every reply carries the whole state.
async function step(fn) {
  if (ui.busy) return;
  ui.busy = true;
  setEnabled(false);
  try { await fn(); } catch (e) { $('status').innerHTML = '<span class="err"></span>'; $('status').firstChild.textContent = e.message; }
  ui.busy = false;
  setEnabled(true);
  document.body.dataset.busy = '0';
}

function setEnabled(on) {
  document.body.dataset.busy = on ? '0' : '1';
  for (const b of document.querySelectorAll('#controls button, #send, #undo, #reset')) b.disabled = !on || !ui.session;
}

async function start() {
  await step(async () => {
    if (ui.session) api('DELETE', '/api/sessions/' + ui.session).catch(() => {});
    $('log').innerHTML = '';
    const s = await api('POST', '/api/sessions', { dataset: $('dataset').value, problem: $('problem').value,
                                                   plan: $('plan').value, method: $('method').value });
    ui.session = s.id;
    log('started ' + s.dataset + ' problem ' + s.problem + ' (' + s.plan + ')');
    show(s);
    await maybeAssist(s);
  });
}

// After the human's turn the assistant acts by the chosen method.
async function maybeAssist(s) {
  while (s.turn === s.assistant && !s.reached_goal) {
    const r = await api('POST', `/api/sessions/${ui.session}/assist`, { apply: true });
    log(r.decision.action, 'robot');
    s = r.state;
    show(s);
  }
  return s;
}

async function act(action) {
  await step(async () => {
    const s = await api('POST', `/api/sessions/${ui.session}/act`, { action });
    log(action);
    show(s);
    await maybeAssist(s);
  });
}

async function say(text) {
  await step(async () => {
    const s = await api('POST', `/api/sessions/${ui.session}/hear`, { utterance: text });
    log('"' + text + '"', 'say');
    show(s);
  });
}

function humanAction(kind) {
  const s = ui.state;
  if (!s) return null;
  return s.actions.find((a) => a.startsWith('(' + kind + ' ' + s.principal)) || null;
}

function move(dir) {
  if (!ui.state || ui.busy) return;
  const a = humanAction(dir);
  if (a) act(a); else log('cannot move ' + dir + ' now', 'err');
}

// ---- drawing --------------------------------------------------------------

function show(s) {
  ui.state = s;
  const done = s.reached_goal;
  $('status').className = done ? 'done' : '';
  $('status').textContent = done ? `Goal reached: ${done} (step ${s.t}).`
    : `Step ${s.t}: ${s.turn === s.principal ? 'your move' : 'the assistant is thinking'}.`;
  $('modality').textContent = '(' + s.posterior.modality + ' evidence)';
  if (s.scene.kind === 'grid') drawGrid(s.scene); else drawHome(s.scene);
  drawVerbs(s);
  drawBars(s.posterior.goals);
  drawChart(s);
  drawReading(s.reading);
  drawDecision(s.decision);
}

function drawGrid(sc) {
  const cv = $('grid');
  cv.hidden = false; $('home').hidden = true; $('controls').hidden = false;
  const cell = Math.floor(Math.min(480 / sc.width, 480 / sc.height));
  cv.width = cell * sc.width; cv.height = cell * sc.height;
  const g = cv.getContext('2d');
  g.clearRect(0, 0, cv.width, cv.height);
  for (let y = 0; y < sc.height; y++)
    for (let x = 0; x < sc.width; x++) {
      g.fillStyle = sc.walls[y][x] === '#' ? '#444' : '#fff';
      g.fillRect(x * cell, y * cell, cell, cell);
      g.strokeStyle = '#e4e4e4';
      g.strokeRect(x * cell + 0.5, y * cell + 0.5, cell - 1, cell - 1);
    }
  const at = (o) => [(o.x - 1) * cell, (o.y - 1) * cell];
  const colour = (o) => COLOURS[o.colour] || COLOURS[''];
  const held = {};
  for (const o of sc.objects) if (o.held_by) (held[o.held_by] = held[o.held_by] || []).push(o);
  const order = { door: 0, gem: 1, key: 2, robot: 3, human: 4 };
  const objs = sc.objects.filter((o) => !o.held_by).sort((a, b) => order[a.kind] - order[b.kind]);
  for (const o of objs) {
    const [px, py] = at(o);
    if (o.kind === 'door') {
      g.fillStyle = colour(o);
      g.globalAlpha = o.locked ? 1 : 0.25;
      g.fillRect(px + 2, py + 2, cell - 4, cell - 4);
      g.globalAlpha = 1;
      if (o.locked) { g.fillStyle = '#fff'; g.fillRect(px + cell * 0.42, py + cell * 0.35, cell * 0.16, cell * 0.3); }
    } else if (o.kind === 'gem') {
      drawGem(g, px + cell / 2, py + cell / 2, cell * 0.34, colour(o));
    } else if (o.kind === 'key') {
      drawKey(g, px + cell / 2, py + cell / 2, cell * 0.3, colour(o));
    } else {
      drawAgent(g, o, px, py, cell, sc.active === o.name);
    }
  }
  for (const name in held) {
    const a = sc.objects.find((o) => o.name === name);
    if (!a || a.x === undefined) continue;
    const [px, py] = at(a);
    held[name].forEach((o, i) => {
      const cx = px + cell * (0.2 + 0.3 * i), cy = py + cell * 0.82;
      if (o.kind === 'key') drawKey(g, cx, cy, cell * 0.16, colour(o)); else drawGem(g, cx, cy, cell * 0.14, colour(o));
    });
  }
}

function drawAgent(g, o, px, py, cell, active) {
  g.fillStyle = o.kind === 'human' ? '#f28e2b' : '#4e79a7';
  g.beginPath();
  if (o.kind === 'human') g.arc(px + cell / 2, py + cell / 2, cell * 0.36, 0, 2 * Math.PI);
  else g.rect(px + cell * 0.16, py + cell * 0.16, cell * 0.68, cell * 0.68);
  g.fill();
  if (active) { g.lineWidth = 3; g.strokeStyle = '#111'; g.stroke(); g.lineWidth = 1; }
  g.fillStyle = '#fff';
  g.font = `bold ${Math.floor(cell * 0.4)}px sans-serif`;
  g.textAlign = 'center'; g.textBaseline = 'middle';
  g.fillText(o.kind === 'human' ? 'H' : 'R', px + cell / 2, py + cell / 2);
}

function drawGem(g, cx, cy, r, fill) {
  g.fillStyle = fill;
  g.beginPath();
  g.moveTo(cx, cy - r); g.lineTo(cx + r, cy); g.lineTo(cx, cy + r); g.lineTo(cx - r, cy);
  g.closePath(); g.fill();
  g.strokeStyle = '#333'; g.stroke();
}

function drawKey(g, cx, cy, r, fill) {
  g.strokeStyle = fill; g.fillStyle = fill; g.lineWidth = Math.max(2, r * 0.35);
  g.beginPath(); g.arc(cx - r * 0.5, cy, r * 0.45, 0, 2 * Math.PI); g.stroke();
  g.beginPath(); g.moveTo(cx - r * 0.05, cy); g.lineTo(cx + r, cy); g.lineTo(cx + r, cy + r * 0.5); g.stroke();
  g.lineWidth = 1;
}

function drawHome(sc) {
  $('grid').hidden = true; $('controls').hidden = false;
  const home = $('home');
  home.hidden = false;
  home.innerHTML = '';
  home.className = 'cards';
  for (const f of sc.fixtures) {
    const card = document.createElement('div');
    card.className = 'card';
    const h = document.createElement('h3'); h.textContent = f.name; card.appendChild(h);
    for (const a of sc.agents.filter((a) => a.at === f.name)) {
      const d = document.createElement('div');
      d.className = 'agent ' + a.kind;
      d.textContent = a.name + (a.held.length ? ' holding ' + a.held.join(', ') : '') + (sc.active === a.name ? ' *' : '');
      card.appendChild(d);
    }
    for (const p of f.piles) {
      const d = document.createElement('div'); d.className = 'pile'; d.textContent = p.join(' on '); card.appendChild(d);
    }
    home.appendChild(card);
  }
}

// Buttons for the human's applicable non-move actions (pick up, unlock, hand over, wait, ...).
function drawVerbs(s) {
  const box = $('verbs');
  box.innerHTML = '';
  const moves = ['up', 'down', 'left', 'right'];
  const mine = s.actions.filter((a) => !moves.some((m) => a.startsWith('(' + m + ' ')));
  const arrows = document.querySelector('.arrows');
  arrows.hidden = s.scene.kind !== 'grid';
  for (const a of mine) {
    const b = document.createElement('button');
    b.textContent = a.slice(1, -1).replace(/^pickup/, 'pick up').replace(/^handover/, 'hand over');
    b.dataset.action = a;
    b.onclick = () => act(a);
    b.disabled = ui.busy;
    box.appendChild(b);
  }
  if (!mine.length && s.turn !== s.principal) box.textContent = '';
}

function goalColour(g, i) { return COLOURS[g.colour] && g.colour ? COLOURS[g.colour] : SERIES[i % SERIES.length]; }

function drawBars(goals) {
  const box = $('bars');
  box.innerHTML = '';
  goals.forEach((g, i) => {
    const row = document.createElement('div');
    row.className = 'bar';
    row.dataset.goal = g.goal;
    row.dataset.p = g.p.toFixed(6);
    row.innerHTML = '<span class="label"></span><span class="track"><span class="fill"></span></span><span class="value"></span>';
    row.querySelector('.label').textContent = g.goal;
    const fill = row.querySelector('.fill');
    fill.style.display = 'block';
    fill.style.width = (100 * g.p).toFixed(1) + '%';
    fill.style.background = goalColour(g, i);
    row.querySelector('.value').textContent = g.p.toFixed(2);
    box.appendChild(row);
  });
}

function drawChart(s) {
  const cv = $('chart'), g = cv.getContext('2d');
  const W = cv.width, H = cv.height, L = 30, B = 18, T = 6;
  g.clearRect(0, 0, W, H);
  g.strokeStyle = '#999'; g.fillStyle = '#666'; g.font = '10px sans-serif';
  g.beginPath(); g.moveTo(L, T); g.lineTo(L, H - B); g.lineTo(W - 4, H - B); g.stroke();
  for (const v of [0, 0.5, 1]) {
    const y = H - B - v * (H - B - T);
    g.fillText(v.toFixed(1), 4, y + 3);
  }
  const hist = s.history, n = hist.length;
  g.fillText('update', W - 40, H - 4);
  const xOf = (i) => L + (n <= 1 ? 0 : (i / (n - 1)) * (W - L - 8));
  const yOf = (p) => H - B - p * (H - B - T);
  s.posterior.goals.forEach((goal, k) => {
    g.strokeStyle = goalColour(goal, k); g.lineWidth = 2;
    g.beginPath();
    hist.forEach((h, i) => { const x = xOf(i), y = yOf(h.goals[k]); if (i) g.lineTo(x, y); else g.moveTo(x, y); });
    g.stroke();
  });
  g.lineWidth = 1;
}

function table(rows, chosen) {
  const t = document.createElement('table');
  for (const [a, b] of rows) {
    const tr = t.insertRow();
    if (chosen !== undefined && a === chosen) tr.className = 'chosen';
    tr.insertCell().textContent = a;
    const c = tr.insertCell(); c.className = 'num'; c.textContent = b;
  }
  return t;
}

function drawReading(r) {
  const box = $('reading');
  box.innerHTML = '';
  if (!r) { box.textContent = 'No instruction yet.'; return; }
  const p = document.createElement('div');
  p.textContent = `"${r.utterance}" (${r.source}):`;
  box.appendChild(p);
  box.appendChild(table(r.commands.map((c) => [c.command, c.p.toFixed(3)])));
}

function drawDecision(d) {
  const box = $('decision');
  box.innerHTML = '';
  if (!d) { box.textContent = 'The assistant has not acted yet.'; return; }
  const p = document.createElement('div');
  p.textContent = `${d.action}: ${d.reason}` + (d.command ? ` (command ${d.command}, p = ${d.command_probability.toFixed(2)})` : '');
  box.appendChild(p);
  if (d.candidates.length) {
    const rows = d.candidates.slice().sort((a, b) => (b.value ?? -1e9) - (a.value ?? -1e9))
      .map((c) => [c.action, c.value === null ? 'dead end' : c.value.toFixed(2)]);
    const cap = document.createElement('div'); cap.textContent = 'expected value (negated cost to go) per candidate:';
    box.appendChild(cap);
    box.appendChild(table(rows, d.action));
  }
}

// ---- wiring ----------------------------------------------------------------

$('dataset').onchange = onDataset;
$('problem').onchange = onProblem;
$('start').onclick = start;
$('reset').onclick = () => step(async () => { $('log').innerHTML = ''; show(await api('POST', `/api/sessions/${ui.session}/reset`)); });
$('undo').onclick = () => step(async () => { show(await api('POST', `/api/sessions/${ui.session}/undo`)); log('(undo)'); });
$('method').onchange = () => {
  if (!ui.session) return;
  step(async () => { show(await api('POST', `/api/sessions/${ui.session}/method`, { method: $('method').value })); });
};
$('say').onsubmit = (e) => {
  e.preventDefault();
  const text = $('utterance').value.trim();
  if (text && ui.session) { say(text); $('utterance').value = ''; }
};
for (const b of document.querySelectorAll('[data-move]')) b.onclick = () => move(b.dataset.move);
document.addEventListener('keydown', (e) => {
  if (e.target.tagName === 'INPUT') return;
  const dir = { ArrowUp: 'up', ArrowDown: 'down', ArrowLeft: 'left', ArrowRight: 'right' }[e.key];
  if (dir && ui.session) { e.preventDefault(); move(dir); }
});
loadCatalogue().catch((e) => { $('status').textContent = 'Cannot reach the server: ' + e.message; });
