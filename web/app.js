// The clips play page: talks to the JSON API of `clips serve` (docs/api.md).
// Plain JS, no libraries, nothing fetched from outside the server.
//
// Requests go one at a time (enqueue/pump). While one is in flight the
// assistant is thinking: the page says so, Start, Say, the menus and the move
// buttons are disabled, and a key pressed then is not played (nor queued for
// later, in a state the player has not seen); it is counted in ui.ignoredKeys.
'use strict';

const COLOURS = { red: '#d62728', yellow: '#e6b800', blue: '#1f77b4', green: '#2ca02c', pink: '#e377c2',
                  orange: '#ff7f0e', purple: '#9467bd', '': '#888' };
const SERIES = ['#d62728', '#1f77b4', '#2ca02c', '#e6b800', '#9467bd', '#8c564b', '#e377c2', '#17becf', '#7f7f7f'];
// Dash patterns and point markers of the chart's lines: 5 x 6 distinct pairs,
// so that lines with equal values still show each other.
const DASHES = [[], [7, 4], [2, 3], [9, 3, 2, 3], [4, 2, 1, 2]];
const MARKERS = ['circle', 'square', 'triangle', 'diamond', 'cross', 'bar'];
const METHOD_NAMES = { clips: 'CLIPS', lang_only: 'language-only', action_only: 'action-only', literal: 'the literal listener' };
const KEY_MOVES = { ArrowUp: 'up', ArrowDown: 'down', ArrowLeft: 'left', ArrowRight: 'right' };
const $ = (id) => document.getElementById(id);

const ui = { catalogue: null, session: null, state: null, busy: false, queue: [], maxQueued: 0, chartStyles: [],
             utteranceBytes: 500, ignoredKeys: 0, thinkingTimer: null };
window.clips = ui;  // for tests and the curious

// Errors in words: the server's own message, or what went wrong on the way.
async function api(method, path, body) {
  let res;
  try {
    res = await fetch(path, {
      method, headers: body ? { 'Content-Type': 'application/json' } : {},
      body: body ? JSON.stringify(body) : undefined,
    });
  } catch (e) {
    throw new Error('cannot reach the server (is clips serve still running?)');
  }
  let data;
  try { data = await res.json(); } catch (e) {
    throw new Error(`the server answered HTTP ${res.status} without a JSON reply`);
  }
  if (!res.ok) throw new Error(data.error || ('HTTP ' + res.status));
  return data;
}

// A line of the log, numbered by the step it led to (`step`; none for notes).
function log(text, cls, step) {
  const li = document.createElement('li');
  li.textContent = text;
  if (step !== undefined) li.dataset.step = String(step);
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
  // A problem without a recorded plan plays too: its goals follow the pack's rule.
  fillSelect($('plan'), p && p.plans.length ? p.plans : [''], (v) => v || '(no recorded plan)');
  onPlan();
}
// The player's goal, kept from the assistant: the plan's true goal, none, or
// any candidate goal of the problem.
function onPlan() {
  const ds = currentDataset();
  const p = ds && ds.problems.find((q) => q.id === $('problem').value);
  const choices = ($('plan').value ? ['plan'] : []).concat(['none'], p && p.goals ? p.goals : []);
  fillSelect($('goal'), choices, (v) => v === 'plan' ? "the plan's goal" : v === 'none' ? 'none (play freely)' : v);
}

async function loadCatalogue() {
  ui.catalogue = await api('GET', '/api/datasets');
  if (ui.catalogue.limits) ui.utteranceBytes = ui.catalogue.limits.utterance_bytes;
  fillSelect($('dataset'), ui.catalogue.datasets.map((d) => d.name));
  onDataset();
  updateBytes();
}

// ---- the queue: one request at a time, in the order asked -------------------

function enqueue(kind, run) {
  ui.queue.push({ kind, run });
  showQueue();
  pump();
}

async function pump() {
  if (ui.busy) return;
  ui.busy = true;
  setEnabled(false);
  while (ui.queue.length) {
    const task = ui.queue.shift();
    showQueue();
    try { await task.run(); } catch (e) { showError(e.message); }
  }
  ui.busy = false;
  setEnabled(true);
  showQueue();
}

function showError(message) {
  $('status').innerHTML = '<span class="err"></span>';
  $('status').firstChild.textContent = message;
}

function showQueue() {
  const moves = ui.queue.filter((t) => t.kind === 'move').length;
  if (ui.busy) ui.maxQueued = Math.max(ui.maxQueued, moves);  // the most keys that ever waited behind a request (tests read it)
  $('status').dataset.queued = String(moves);
  const q = $('queued');
  if (q) q.textContent = moves ? ` (${moves} key${moves > 1 ? 's' : ''} queued)` : '';
}

function setEnabled(on) {
  document.body.dataset.busy = on ? '0' : '1';
  // Said after a moment, so that quick answers do not flicker.
  clearTimeout(ui.thinkingTimer);
  if (on) $('thinking').hidden = true;
  else ui.thinkingTimer = setTimeout(() => { $('thinking').hidden = !ui.busy; }, 150);
  for (const e of document.querySelectorAll('#start, #dataset, #problem, #plan, #goal, #method')) e.disabled = !on;
  const done = !!(ui.state && ui.state.reached_goal);
  for (const b of document.querySelectorAll('#undo, #reset')) b.disabled = !on || !ui.session;
  for (const b of document.querySelectorAll('#controls button')) b.disabled = !on || !ui.session || done;
  updateBytes();
}

// Keys and buttons act on the board: give it the focus back, so the arrow
// keys work at once after typing an instruction or clicking a button.
function focusBoard() { $('board').focus({ preventScroll: true }); }

function start() {
  enqueue('start', async () => {
    if (ui.session) api('DELETE', '/api/sessions/' + ui.session).catch(() => {});
    ui.session = null;
    ui.queue = ui.queue.filter((t) => t.kind !== 'move');
    $('log').innerHTML = '';
    const body = { dataset: $('dataset').value, problem: $('problem').value, method: $('method').value };
    if ($('plan').value) body.plan = $('plan').value;
    if ($('goal').value === 'none') body.goal = null;
    else if ($('goal').value !== 'plan') body.goal = $('goal').value;
    const s = await api('POST', '/api/sessions', body);
    ui.session = s.id;
    log('started ' + s.dataset + ' problem ' + s.problem + (s.plan ? ' (' + s.plan + ')' : ' (no recorded plan)'));
    show(s);
    await maybeAssist(s);
  });
}

// After the human's turn the assistant acts by the chosen method.
async function maybeAssist(s) {
  while (s.turn === s.assistant && !s.reached_goal) {
    const r = await api('POST', `/api/sessions/${ui.session}/assist`, { apply: true });
    log(r.decision.action, 'robot', r.state.t);
    s = r.state;
    show(s);
  }
  return s;
}

async function doAct(action) {
  const s = await api('POST', `/api/sessions/${ui.session}/act`, { action });
  log(action, '', s.t);
  show(s);
  await maybeAssist(s);
}

function goalNote() {
  return `the goal is reached (${goalWords(ui.state, ui.state.reached_goal)}): no more moves; Undo or Reset to play on`;
}

function act(action) {
  if (!ui.session) return;
  enqueue('act', async () => {
    if (ui.state.reached_goal) { log(goalNote(), 'err'); return; }
    await doAct(action);
  });
}

// A key: which action it means is decided when its turn in the queue comes,
// in the state the earlier keys and the robot's replies led to.
function move(dir) {
  if (!ui.session) return;
  if (ui.busy) {  // thinking: the key is not played
    ui.ignoredKeys++;
    $('thinking').hidden = false;
    return;
  }
  if (ui.state && ui.state.reached_goal && !ui.busy) { log(goalNote(), 'err'); return; }
  enqueue('move', async () => {
    if (ui.state.reached_goal) { log(goalNote(), 'err'); return; }
    const a = dir === 'noop' ? ui.state.noop_action && ui.state.actions.includes(ui.state.noop_action) && ui.state.noop_action
                             : humanAction(dir);
    if (a) await doAct(a); else log((dir === 'noop' ? 'cannot wait' : 'cannot move ' + dir) + ' now', 'err');
  });
}

function utf8Bytes(text) { return new TextEncoder().encode(text).length; }

function say(text) {
  if (!ui.session) return;
  enqueue('say', async () => {
    $('say-error').hidden = true;
    try {
      const s = await api('POST', `/api/sessions/${ui.session}/hear`, { utterance: text });
      log('"' + text + '"', 'say', s.t);
      // Only now is it heard: the box is cleared unless it holds something new.
      if ($('utterance').value.trim() === text) $('utterance').value = '';
      updateBytes();
      show(s);
    } catch (e) {
      // A rejected instruction stays in the box, with the reason beside it.
      $('say-error').textContent = 'Not heard: ' + e.message;
      $('say-error').hidden = false;
      throw e;
    }
  });
}

function humanAction(kind) {
  const s = ui.state;
  if (!s) return null;
  return s.actions.find((a) => a.startsWith('(' + kind + ' ' + s.principal)) || null;
}

// The instruction box counts UTF-8 bytes, as the server does.
function updateBytes() {
  const n = utf8Bytes($('utterance').value.trim()), max = ui.utteranceBytes;
  const over = n > max;
  $('bytes').textContent = `${n}/${max} bytes`;
  $('bytes').className = over ? 'err' : '';
  $('send').disabled = !ui.session || ui.busy || over || n === 0;
  if (over) {
    $('say-error').textContent = `Too long: ${n} bytes; the server takes at most ${max} bytes (UTF-8; letters such as é take two).`;
    $('say-error').hidden = false;
  } else if ($('say-error').textContent.startsWith('Too long')) {
    $('say-error').hidden = true;
  }
}

// ---- drawing --------------------------------------------------------------

// The goal menu says the candidate goals in words once a session of its
// dataset and problem has shown its scene (the label stays the value and the
// tooltip); before that it can only list labels.
function goalMenuInWords(s) {
  if (s.dataset !== $('dataset').value || String(s.problem) !== $('problem').value) return;
  for (const o of $('goal').options) {
    if (o.value === 'plan' || o.value === 'none') continue;
    o.textContent = goalWords(s, o.value);
    o.title = o.value;
  }
}

function show(s) {
  ui.state = s;
  goalMenuInWords(s);
  const done = s.reached_goal;
  if (done) {
    const dropped = ui.queue.filter((t) => t.kind === 'move').length;
    if (dropped) log(`${dropped} queued key${dropped > 1 ? 's' : ''} not played: the goal is reached`, 'err');
    ui.queue = ui.queue.filter((t) => t.kind !== 'move');
  }
  $('status').className = done ? 'done' : '';
  // Goals in words, as on the bars; their labels in the tooltip.
  const others = (s.goals_holding || []).filter((g) => g !== s.player_goal);
  const said = (g) => goalWords(s, g);
  $('status').textContent = done ? `Goal reached: ${said(done)} (step ${s.t}). The board takes no more moves: Undo or Reset to play on.`
    : `Step ${s.t}: ${s.turn === s.principal ? 'your move' : 'the assistant is thinking'}.` +
      (s.player_goal ? ` Your goal: ${said(s.player_goal)} (the assistant is not told).` : ' No goal of your own: play freely.') +
      (others.length ? ` ${others.map(said).join('; ')}: ${others.length > 1 ? 'these hold' : 'this holds'}, not yours: play on.` : '');
  $('status').title = [done || s.player_goal, ...others].filter(Boolean).join(', ');
  const q = document.createElement('span'); q.id = 'queued'; $('status').appendChild(q);
  showQueue();
  $('board').classList.toggle('done', !!done);
  $('modality').textContent = '(' + s.posterior.modality + ' evidence)';
  if (s.scene.kind === 'grid') drawGrid(s.scene);
  else if (s.scene.kind === 'home') drawHome(s.scene);
  else drawText(s.scene);
  drawVerbs(s);
  drawBars(s.posterior.goals);
  drawChart(s);
  drawReading(s.reading);
  drawDecision(s);
  setEnabled(!ui.busy);
}

function showOnly(id) {
  for (const x of ['grid', 'home', 'textscene']) $(x).hidden = x !== id;
  $('controls').hidden = false;
}

function drawGrid(sc) {
  const cv = $('grid');
  showOnly('grid');
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
  const objs = sc.objects.filter((o) => !o.held_by && o.x !== undefined).sort((a, b) => order[a.kind] - order[b.kind]);
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
  showOnly('home');
  const home = $('home');
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

function el(tag, cls, text) {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  if (text !== undefined) e.textContent = text;
  return e;
}

function named(o) {
  const words = (o.qualities || []).concat(o.states || []);
  return o.name + (words.length ? ' (' + words.join(', ') + ')' : '');
}

// Every thing a text scene shows (at places, held, in other things, on its
// own), each once, for looking names up.
function sceneThings(sc) {
  const out = [];
  const walk = (o) => { out.push(o); for (const x of o.contents || []) walk(x); };
  for (const p of sc.places || []) for (const o of p.objects || []) walk(o);
  for (const a of sc.agents || []) for (const o of a.holds || []) walk(o);
  for (const o of sc.others || []) walk(o);
  return out;
}

// A thing and, indented below it, what is in or on it ("in: key1 (red)").
function thingBox(o, touched, cls) {
  const d = el('div', cls || 'item', named(o));
  d.dataset.object = o.name;
  if (touched.has(o.name)) d.classList.add('changed');
  if (!(o.contents && o.contents.length)) return d;
  const box = el('div', 'thing');
  box.appendChild(d);
  const inner = el('div', 'contents');
  for (const x of o.contents) {
    const row = thingBox(x, touched);
    const first = row.classList.contains('thing') ? row.firstChild : row;
    first.textContent = x.relation + ': ' + first.textContent;
    inner.appendChild(row);
  }
  box.appendChild(inner);
  return box;
}

// A pack without pictures: its places as cards, what each agent holds, the
// other facts, and what the last step changed. A thing in or on another is
// drawn inside it, and a carried one with its carrier.
function drawText(sc) {
  showOnly('textscene');
  const box = $('textscene');
  box.innerHTML = '';
  const touched = new Set();  // objects named by a fact that just changed
  for (const f of [...sc.changed.added, ...sc.changed.removed])
    for (const w of f.replace(/[()]/g, ' ').split(/\s+/).slice(2)) touched.add(w);
  const agentLine = (a) => {
    const d = el('div', 'agent ' + (a.name === ui.state.principal ? 'human' : 'robot'));
    d.dataset.agent = a.name;
    d.textContent = a.name + (sc.active === a.name ? ' (to move)' : '') + (a.holds.length ? ', holding:' : '');
    if (touched.has(a.name)) d.classList.add('changed');
    if (!a.holds.length) return d;
    const wrap = el('div', 'carrier');
    wrap.appendChild(d);
    const held = el('div', 'contents');
    for (const o of a.holds) held.appendChild(thingBox(o, touched));
    wrap.appendChild(held);
    return wrap;
  };
  const cards = el('div', 'cards');
  for (const p of sc.places) {
    const card = el('div', 'card');
    card.dataset.place = p.name;
    card.appendChild(el('h3', '', named(p)));
    for (const a of sc.agents.filter((a) => a.at === p.name)) card.appendChild(agentLine(a));
    for (const o of p.objects) card.appendChild(thingBox(o, touched));
    if (!p.objects.length) card.appendChild(el('div', 'pile', '(nothing here)'));
    cards.appendChild(card);
  }
  const nowhere = sc.agents.filter((a) => !a.at);
  if (nowhere.length) {
    const card = el('div', 'card');
    card.appendChild(el('h3', '', 'agents'));
    for (const a of nowhere) card.appendChild(agentLine(a));
    cards.appendChild(card);
  }
  // Things that hold something and stand nowhere the scene says.
  for (const o of sc.others || []) {
    const card = el('div', 'card');
    card.dataset.thing = o.name;
    card.appendChild(thingBox(o, touched, 'item holder'));
    cards.appendChild(card);
  }
  box.appendChild(cards);
  if (sc.facts.length) {
    box.appendChild(el('h3', '', 'Facts'));
    const ul = el('ul', 'facts');
    for (const f of sc.facts) ul.appendChild(el('li', sc.changed.added.includes(f) ? 'changed' : '', f));
    box.appendChild(ul);
  }
  const ch = el('div', 'delta');
  ch.id = 'changed';
  if (sc.changed.added.length + sc.changed.removed.length) {
    ch.appendChild(el('span', '', 'Last step: '));
    for (const f of sc.changed.added) ch.appendChild(el('span', 'added', '+ ' + f));
    for (const f of sc.changed.removed) ch.appendChild(el('span', 'removed', '\u2212 ' + f));
  } else {
    ch.textContent = 'Nothing has changed yet.';
  }
  box.appendChild(ch);
}

// Buttons for the human's applicable actions: on a grid the ones the arrows
// do not cover (pick up, unlock, hand over, wait); otherwise every one,
// grouped by action.
function drawVerbs(s) {
  const box = $('verbs');
  box.innerHTML = '';
  const grid = s.scene.kind === 'grid';
  document.querySelector('.arrows').hidden = !grid;
  const moves = ['up', 'down', 'left', 'right'];
  const mine = grid ? s.actions.filter((a) => !moves.some((m) => a.startsWith('(' + m + ' '))) : s.actions;
  const groups = new Map();
  for (const a of mine) {
    const verb = a.slice(1, -1).split(/\s+/)[0];
    if (!groups.has(verb)) groups.set(verb, []);
    groups.get(verb).push(a);
  }
  // Text scenes: the arguments but the human and the place it is at; a
  // place it would go to reads "to PLACE".
  const agent = s.scene.kind === 'text' ? (s.scene.agents || []).find((g) => g.name === s.principal) : null;
  const here = agent ? agent.at : null;
  const places = new Set(s.scene.kind === 'text' ? (s.scene.places || []).map((p) => p.name) : []);
  const label = (a) => {
    const words = a.slice(1, -1).split(/\s+/);
    if (grid || s.scene.kind === 'home') return words.join(' ').replace(/^pickup/, 'pick up').replace(/^handover/, 'hand over');
    const args = words.slice(1);
    const leaving = here && args.includes(here);
    return args.filter((w) => w !== s.principal && w !== here)
      .map((w) => (leaving && places.has(w) ? 'to ' + w : w)).join(' ') || words[0];
  };
  for (const [verb, actions] of groups) {
    const row = grid || s.scene.kind === 'home' ? box : el('div', 'verb');
    if (row !== box) { row.appendChild(el('span', 'verb-name', verb)); box.appendChild(row); }
    for (const a of actions) {
      const b = el('button', '', label(a));
      b.dataset.action = a;
      b.title = a;
      b.onclick = () => act(a);
      b.disabled = ui.busy || !!s.reached_goal;
      row.appendChild(b);
    }
  }
}

// A goal in words, from its PDDL condition and what the scene says of the
// objects: each atom as "subject predicate object", names without their
// numbers and with their qualities ("human has the yellow gem", "stool
// made"); connectives and variables are left out. The label stays in the
// tooltip, the condition one hover away.
function objectWords(s, name) {
  if (name === s.principal || name === s.assistant) return name;
  const quals = [];
  const sc = s.scene;
  if (sc.kind === 'grid') {
    const o = (sc.objects || []).find((x) => x.name === name);
    if (o && o.colour) quals.push(o.colour);
  } else if (sc.kind === 'text') {
    const o = sceneThings(sc).find((x) => x.name === name) || (sc.places || []).find((x) => x.name === name);
    if (o) quals.push(...(o.qualities || []));
  }
  // A number tells places apart ("shelf 3"); of other things the kind is said ("the red key").
  const place = sc.kind === 'text' && (sc.places || []).some((p) => p.name === name);
  const noun = place ? name.replace(/[-_]+/g, ' ').replace(/([^\d\s])(\d+)$/, '$1 $2')
                     : name.replace(/[-_]+/g, ' ').replace(/\s*\d+$/, '');
  return 'the ' + quals.concat([noun]).join(' ');
}

function goalWords(s, label) {
  const cond = s.goal_conditions && s.goal_conditions[label];
  if (!cond) return label;
  const atoms = [...cond.matchAll(/\(([^()]+)\)/g)].map((m) => m[1].trim().split(/\s+/))
    .filter((w) => w.length && !['and', 'or', 'not', 'exists', 'forall', '='].includes(w[0]) && !w.some((x) => x.startsWith('?')));
  if (!atoms.length) return label;
  return atoms.map(([pred, ...args]) => {
    const verb = pred.replace(/[-_]+/g, ' ');
    const words = args.map((a) => objectWords(s, a));
    return words.length === 1 ? `${words[0].replace(/^the /, '')} ${verb}`
      : [words[0], verb, ...words.slice(1)].join(' ');
  }).join(', and ');
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
    const s = ui.state;
    row.querySelector('.label').textContent = s ? goalWords(s, g.goal) : g.goal;
    row.querySelector('.label').title = g.goal + (s && s.goal_conditions ? ': ' + (s.goal_conditions[g.goal] || '') : '') +
      (s && s.player_goal === g.goal ? ' (your goal)' : '');
    const fill = row.querySelector('.fill');
    fill.style.display = 'block';
    fill.style.width = (100 * g.p).toFixed(1) + '%';
    fill.style.background = goalColour(g, i);
    row.querySelector('.value').textContent = g.p.toFixed(2);
    box.appendChild(row);
  });
}

function drawMarker(g, shape, x, y, r) {
  g.beginPath();
  if (shape === 'circle') g.arc(x, y, r, 0, 2 * Math.PI);
  else if (shape === 'square') g.rect(x - r, y - r, 2 * r, 2 * r);
  else if (shape === 'triangle') { g.moveTo(x, y - r - 1); g.lineTo(x + r + 1, y + r); g.lineTo(x - r - 1, y + r); g.closePath(); }
  else if (shape === 'diamond') { g.moveTo(x, y - r - 1); g.lineTo(x + r + 1, y); g.lineTo(x, y + r + 1); g.lineTo(x - r - 1, y); g.closePath(); }
  if (shape === 'cross' || shape === 'bar') {
    g.save(); g.setLineDash([]); g.lineWidth = 2;
    if (shape === 'cross') { g.moveTo(x - r, y - r); g.lineTo(x + r, y + r); g.moveTo(x + r, y - r); g.lineTo(x - r, y + r); }
    else { g.moveTo(x, y - r - 1); g.lineTo(x, y + r + 1); }
    g.stroke(); g.restore();
  } else {
    g.fill();
  }
}

function seriesStyle(goal, k) {
  return { goal: goal.goal, colour: goalColour(goal, k), dash: DASHES[k % DASHES.length], marker: MARKERS[k % MARKERS.length] };
}

function drawChart(s) {
  const cv = $('chart'), g = cv.getContext('2d');
  const W = cv.width, H = cv.height, L = 30, B = 18, T = 6;
  g.clearRect(0, 0, W, H);
  g.setLineDash([]);
  g.strokeStyle = '#999'; g.fillStyle = '#666'; g.font = '10px sans-serif'; g.textAlign = 'left'; g.textBaseline = 'alphabetic';
  g.beginPath(); g.moveTo(L, T); g.lineTo(L, H - B); g.lineTo(W - 4, H - B); g.stroke();
  for (const v of [0, 0.5, 1]) {
    const y = H - B - v * (H - B - T);
    g.fillText(v.toFixed(1), 4, y + 3);
  }
  const hist = s.history, n = hist.length;
  g.fillText('update', W - 40, H - 4);
  const xOf = (i) => L + (n <= 1 ? 0 : (i / (n - 1)) * (W - L - 8));
  const yOf = (p) => H - B - p * (H - B - T);
  ui.chartStyles = s.posterior.goals.map(seriesStyle);
  ui.chartStyles.forEach((st, k) => {
    g.strokeStyle = st.colour; g.fillStyle = st.colour; g.lineWidth = 2;
    g.setLineDash(st.dash);
    g.beginPath();
    hist.forEach((h, i) => { const x = xOf(i), y = yOf(h.goals[k] ?? 0); if (i) g.lineTo(x, y); else g.moveTo(x, y); });
    g.stroke();
    g.setLineDash([]);
    // Markers on at most ~24 points, so that long games stay readable.
    const every = Math.max(1, Math.ceil(n / 24));
    hist.forEach((h, i) => { if (i % every === 0 || i === n - 1) drawMarker(g, st.marker, xOf(i), yOf(h.goals[k] ?? 0), 2.5); });
  });
  g.lineWidth = 1;
  drawLegend();
}

function drawLegend() {
  const box = $('legend');
  box.innerHTML = '';
  for (const st of ui.chartStyles) {
    const item = el('span', 'key');
    item.dataset.goal = st.goal;
    item.dataset.dash = st.dash.join(',');
    item.dataset.marker = st.marker;
    const c = document.createElement('canvas');
    c.width = 34; c.height = 12;
    const g = c.getContext('2d');
    g.strokeStyle = st.colour; g.fillStyle = st.colour; g.lineWidth = 2;
    g.setLineDash(st.dash);
    g.beginPath(); g.moveTo(1, 6); g.lineTo(33, 6); g.stroke();
    g.setLineDash([]);
    drawMarker(g, st.marker, 17, 6, 3);
    item.appendChild(c);
    // In words, as on the bars; the label as the tooltip.
    item.appendChild(el('span', '', ui.state ? goalWords(ui.state, st.goal) : st.goal));
    item.title = st.goal;
    box.appendChild(item);
  }
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

// A reading in words, from its steps as the server parts them (agent,
// verb, objects), said with the scene's names and qualities as the goals
// are: "robot: pick up the red key, hand it over to human". A goal
// statement says the goal as the bars do ("goal: human has the red gem"). Text that is no command of the
// domain ("(no command: ...)") reads as it is.
function commandWords(s, c) {
  const parts = [];
  if (c.goal) parts.push(`goal: ${goalWords(s, c.goal)}`);
  const seen = new Set();  // a variable said once is "it" after
  let agent, phrases = [];
  const flush = () => { if (phrases.length) parts.push(`${agent}: ${phrases.join(', ')}`); phrases = []; };
  for (const st of c.steps || []) {
    if (st.agent !== agent) { flush(); agent = st.agent; }
    phrases.push(stepWords(s, st, seen));
  }
  flush();
  return parts.length ? parts.join('; ') : c.command.replace(/^\(|\)$/g, '');
}

function stepWords(s, st, seen) {
  const things = [], recipients = [];
  for (const o of st.objects) {
    if (o.name === s.principal || o.name === s.assistant) { recipients.push(o.name); continue; }
    if (!o.name.startsWith('?')) {
      things.push(o.qualities.length && s.scene.kind !== 'text' && s.scene.kind !== 'grid'
        ? 'the ' + o.qualities.concat([o.noun.replace(/\s*\d+$/, '')]).join(' ') : objectWords(s, o.name));
    } else if (seen.has(o.name)) {
      things.push('it');
    } else {
      seen.add(o.name);
      let w = 'the ' + o.qualities.filter((q) => q !== o.noun).concat([o.noun]).join(' ');
      if (o.from) w += ' from ' + objectWords(s, o.from);
      if (o.to) w += ' to ' + objectWords(s, o.to);
      things.push(w);
    }
  }
  const verb = st.verb.split(' ');
  // A phrasal verb takes "it" between its words: "hand it over", "pick it up".
  const head = verb.length === 2 && things[0] === 'it'
    ? [verb[0], 'it', verb[1], ...things.slice(1)].join(' ')
    : [st.verb, ...things].join(' ');
  return head + (recipients.length ? ' to ' + recipients.join(' and ') : '');
}

// Each reading in words with its probability; the command's PDDL form one
// click away (the words open it).
function drawReading(r) {
  const box = $('reading');
  box.innerHTML = '';
  if (!r) { box.textContent = 'No instruction yet.'; return; }
  const p = document.createElement('div');
  p.textContent = `"${r.utterance}" (${r.source}):`;
  box.appendChild(p);
  const t = document.createElement('table');
  t.className = 'readings';
  for (const c of r.commands) {
    const tr = t.insertRow();
    const cell = tr.insertCell();
    const d = el('details', 'pddl');
    const words = el('summary', 'words', commandWords(ui.state, c));
    d.appendChild(words);
    d.appendChild(el('code', '', c.command));
    cell.appendChild(d);
    const num = tr.insertCell(); num.className = 'num'; num.textContent = c.p.toFixed(3);
  }
  box.appendChild(t);
}

// The assistant's latest decision still in the history (the server keeps it
// with the action it chose; undo takes both back).
function drawDecision(s) {
  const box = $('decision'), d = s.decision;
  box.innerHTML = '';
  if (!d) {
    box.textContent = s.t === 0 ? 'The assistant has not acted yet.'
      : 'No decision of the assistant is left in this history: its moves were undone, or it has not decided since the start.';
    return;
  }
  const p = document.createElement('div');
  p.textContent = `${d.action}: ${d.reason}` + (d.command ? ` (command ${d.command}, p = ${d.command_probability.toFixed(2)})` : '');
  box.appendChild(p);
  const when = el('div', 'note', `Decided after step ${d.t} by ${METHOD_NAMES[d.method] || d.method}` +
    (d.method !== s.method ? `, before the switch to ${METHOD_NAMES[s.method] || s.method}` : '') +
    (d.applied ? '.' : ' (not taken).'));
  when.id = 'decision-when';
  box.appendChild(when);
  if (d.candidates.length) {
    const rows = d.candidates.slice().sort((a, b) => (b.value ?? -1e9) - (a.value ?? -1e9))
      .map((c) => [c.action, c.value === null ? 'dead end' : c.value.toFixed(2)]);
    const cap = document.createElement('div'); cap.textContent = 'expected value (negated cost to go) per candidate:';
    box.appendChild(cap);
    box.appendChild(table(rows, d.action));
  }
}

// ---- wiring ----------------------------------------------------------------

$('dataset').onchange = () => { onDataset(); focusBoard(); };
$('problem').onchange = () => { onProblem(); focusBoard(); };
$('plan').onchange = () => { onPlan(); focusBoard(); };
$('goal').onchange = focusBoard;
$('start').onclick = start;
$('reset').onclick = () => enqueue('reset', async () => {
  $('log').innerHTML = '';
  show(await api('POST', `/api/sessions/${ui.session}/reset`));
});
$('undo').onclick = () => enqueue('undo', async () => {
  show(await api('POST', `/api/sessions/${ui.session}/undo`));
  log('(undo)');
});
$('method').onchange = () => {
  focusBoard();
  if (!ui.session) return;
  const method = $('method').value;
  enqueue('method', async () => { show(await api('POST', `/api/sessions/${ui.session}/method`, { method })); });
};
$('utterance').addEventListener('input', updateBytes);
$('say').onsubmit = (e) => {
  e.preventDefault();
  const text = $('utterance').value.trim();
  updateBytes();
  if (!text || !ui.session || ui.busy || utf8Bytes(text) > ui.utteranceBytes) return;  // the counter says why
  say(text);
  focusBoard();
};
for (const b of document.querySelectorAll('[data-move]')) b.onclick = () => move(b.dataset.move);
// Whatever button was clicked, the keys go to the board next.
document.addEventListener('click', (e) => {
  if (e.target.closest && e.target.closest('button')) focusBoard();
});
document.addEventListener('keydown', (e) => {
  const tag = e.target.tagName;
  if (tag === 'INPUT' || tag === 'SELECT' || tag === 'TEXTAREA' || e.altKey || e.ctrlKey || e.metaKey) return;
  const dir = KEY_MOVES[e.key] || (e.key === 'w' || e.key === 'W' ? 'noop' : null);
  if (dir && ui.session) { e.preventDefault(); move(dir); }
});
loadCatalogue().catch((e) => { $('status').textContent = 'Cannot reach the server: ' + e.message; });
