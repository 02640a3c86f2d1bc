// predmon live view: one tile (or, in the compact view, one row) per robot, worst first, kept up to date from
// /status and refreshed at once when /events says that a log has news. Hand-written, no library, nothing fetched from
// elsewhere. Acknowledgements and the alert switches are kept in this browser (localStorage): the server only shows.
'use strict';
import {STATES, STATE_WORDS, alarmOf, isOwn, own} from './words.js';
import {NEEDS_ATTENTION, el, renderRow, renderTile, shownLight, shownState} from './tile.js';

const tilesEl = document.getElementById('tiles');
const emptyEl = document.getElementById('empty');
const logs = new Map(); // log -> its latest JSON from /status
const nodes = new Map(); // log -> its element on the page
const open = new Map(); // a tile section ('models') -> whether it is open, for every tile alike
let view = new URLSearchParams(location.search).get('view') === 'compact' ? 'compact' : 'tiles';
let watching = [];
let scorecards = []; // the models' own, from /status: one per property
const pending = new Set();
let flushTimer = null;

// ---- kept in this browser ------------------------------------------------------------------------------------
function stored(key, fallback) {
  try {
    const v = localStorage.getItem('predmon.' + key);
    return v === null ? fallback : JSON.parse(v);
  } catch (e) {
    return fallback; // storage refused (a private window): nothing is remembered
  }
}

function store(key, value) {
  try {
    localStorage.setItem('predmon.' + key, JSON.stringify(value));
  } catch (e) {
    // as above
  }
}

// An acknowledgement holds for the state it was given in: any change of state (or run, or staleness) lifts it.
const worstState = (t) => (t.worst && !isOwn(t.worst, t) ? t.worst.property + ' ' + t.worst.state : '');
const ackKey = (t) => t.run + '|' + t.state + '|' + t.stale + '|' + worstState(t);
let acks = stored('acks', {});

const ui = {
  acked: (t) => acks[t.log] === ackKey(t),
  acknowledge(t, yes) {
    if (yes) acks[t.log] = ackKey(t); else delete acks[t.log];
    store('acks', acks);
    show();
  },
  isOpen: (key) => open.get(key) === true,
  // Where the models' forecast did no better than the base rate in cross-validation, its probability is no headline.
  noSkill: (t) => scorecards.some(c => c.property === t.property && !c.skill),
  setOpen: (key, isOpen) => open.set(key, isOpen),
};

// ---- order and drawing ---------------------------------------------------------------------------------------
/** Worst first; a log quiet mid-run sorts with the unknown ones; acknowledged after the others of their state. */
function rank(t) {
  // another property violated or warned sorts the robot with the violations or the warnings
  const r = STATES.indexOf(shownState(t));
  return t.stale && r > STATES.indexOf('unknown') ? STATES.indexOf('unknown') : r;
}

function compare(a, b) {
  return rank(a) - rank(b) || (ui.acked(a) ? 1 : 0) - (ui.acked(b) ? 1 : 0)
    || a.name.localeCompare(b.name, undefined, {numeric: true}) || a.log.localeCompare(b.log);
}

function node(t) {
  let n = nodes.get(t.log);
  if (!n) {
    n = el(view === 'compact' ? 'div' : 'article', view === 'compact' ? 'row' : 'tile');
    n.dataset.log = t.log;
    if (view === 'compact') {
      n.tabIndex = 0;
      n.addEventListener('click', () => showInFull(n.dataset.log));
      n.addEventListener('keydown', (e) => { if (e.key === 'Enter') showInFull(n.dataset.log); });
    }
    nodes.set(t.log, n);
  }
  n.dataset.state = t.state;
  n.dataset.light = shownLight(t);
  n.dataset.stale = String(t.stale);
  n.dataset.run = String(t.run);
  n.dataset.ack = String(ui.acked(t));
  // Drawn again only when something shown changed (the quiet time counts in whole seconds).
  const sig = JSON.stringify([t, ui.acked(t), ui.single, Math.floor(t.quietSeconds)],
    (k, v) => k === 'quietSeconds' ? 0 : v);
  if (n.sig !== sig) {
    n.sig = sig;
    if (view === 'compact') renderRow(n, t, ui); else renderTile(n, t, ui);
  }
  return n;
}

function show() {
  const all = [...logs.values()].sort(compare);
  ui.single = all.length === 1;
  const order = all.map(node);
  // Moved only when the order changed, so that a tile being read does not jump on every refresh.
  if (order.length !== tilesEl.children.length || order.some((n, i) => tilesEl.children[i] !== n)) {
    tilesEl.replaceChildren(...order);
  }
  tilesEl.className = view + (all.length === 1 ? ' single' : '');
  document.body.dataset.view = view;
  emptyEl.hidden = all.length > 0;
  if (all.length === 0) {
    const list = document.getElementById('watching');
    list.replaceChildren(...(watching.length ? watching : ['the logs given to watch']).map(w => el('li', null, w)));
  }
  summary(all);
}

function summary(all) {
  const count = (s) => all.filter(t => shownState(t) === s).length;
  // "2 violations", "1 warning": the words that count take a plural; "ok", "unknown", "run ended" do not
  const word = (s, n) => STATE_WORDS[s].toLowerCase() + (n > 1 && (s === 'violation' || s === 'warning') ? 's' : '');
  const parts = STATES.filter(s => count(s) > 0).map(s => count(s) + ' ' + word(s, count(s)));
  const stale = all.filter(t => t.stale).length;
  const acked = all.filter(t => ui.acked(t)).length;
  document.getElementById('summary').textContent = all.length + (all.length === 1 ? ' robot' : ' robots')
    + (parts.length ? ': ' + parts.join(', ') : '') + (stale ? ' \u00b7 ' + stale + ' stale' : '')
    + (acked ? ' \u00b7 ' + acked + ' acknowledged' : '');
  const worst = all.length ? shownState(all[0]) : 'waiting';
  document.title = (NEEDS_ATTENTION.has(worst) && !ui.acked(all[0]) ? STATE_WORDS[worst] + ' \u2014 ' : '')
    + 'predmon live';
}

function setView(v) {
  view = v;
  nodes.clear();
  tilesEl.replaceChildren();
  const url = new URL(location.href);
  if (v === 'compact') url.searchParams.set('view', 'compact'); else url.searchParams.delete('view');
  history.replaceState(null, '', url);
  document.getElementById('view').textContent = v === 'compact' ? 'show tiles' : 'compact view';
  show();
}

function showInFull(log) {
  setView('tiles');
  const n = nodes.get(log);
  if (n) n.scrollIntoView({block: 'start'});
}

// ---- alerts: opt-in, in this browser -------------------------------------------------------------------------
let notify = stored('notify', false);
let sound = stored('sound', false);
let audio = null;

function beep() {
  if (!audio) audio = new AudioContext();
  if (audio.state === 'suspended') audio.resume();
  for (const [at, f] of [[0, 880], [0.22, 660]]) {
    const o = audio.createOscillator();
    const g = audio.createGain();
    o.frequency.value = f;
    g.gain.setValueAtTime(0.2, audio.currentTime + at);
    g.gain.exponentialRampToValueAtTime(0.001, audio.currentTime + at + 0.18);
    o.connect(g).connect(audio.destination);
    o.start(audio.currentTime + at);
    o.stop(audio.currentTime + at + 0.2);
  }
}

function alert(t) {
  if (ui.acked(t)) return;
  const other = alarmOf(t); // the worst property, when it is not the forecast's
  const title = t.name + ': ' + (other ? other.property + ' ' + other.state : STATE_WORDS[t.state]);
  const body = other ? other.words + (other.action ? '\nDo now: ' + other.action : '')
    : (own(t) === 'warning' && t.warning ? t.warning.reason : '') + (t.action ? '\nDo now: ' + t.action : '');
  if (notify && 'Notification' in window && Notification.permission === 'granted') {
    new Notification(title, {body: body, tag: t.log});
  }
  if (sound) beep();
}

function switches() {
  const n = document.getElementById('notify');
  const available = 'Notification' in window && window.isSecureContext;
  n.disabled = !available;
  n.textContent = !available ? 'notifications: need localhost or https'
    : notify && Notification.permission === 'granted' ? 'notifications on' : 'notifications off';
  n.setAttribute('aria-pressed', String(notify));
  const s = document.getElementById('sound');
  s.textContent = sound ? 'sound on' : 'sound off';
  s.setAttribute('aria-pressed', String(sound));
}

document.getElementById('notify').addEventListener('click', async () => {
  if (!notify && Notification.permission !== 'granted') await Notification.requestPermission();
  notify = !notify && Notification.permission === 'granted';
  store('notify', notify);
  switches();
});
document.getElementById('sound').addEventListener('click', () => {
  sound = !sound;
  store('sound', sound);
  if (sound) beep(); // the click lets the page make a sound from now on, and says what it sounds like
  switches();
});
document.getElementById('view').addEventListener('click', () => setView(view === 'compact' ? 'tiles' : 'compact'));

// ---- data ----------------------------------------------------------------------------------------------------
// Answers may arrive out of order (a full refresh overtaken by one log's): each log keeps the newest request's.
let requests = 0;
const answered = new Map(); // log -> the number of the request whose answer it shows

/** The models' scorecards, in one line under the header. */
function showScorecards() {
  const p = document.getElementById('scorecard');
  p.hidden = scorecards.length === 0;
  p.dataset.skill = String(scorecards.every(c => c.skill));
  p.replaceChildren(...scorecards.flatMap((c, i) => [i > 0 ? ' \u00b7 ' : '',
    el('b', null, (scorecards.length > 1 ? c.property + ': ' : '') + c.summary),
    c.skill ? '' : ' \u2014 the forecast has no skill on these models']));
}

function apply(s, full, request) {
  document.getElementById('stale-after').textContent = s.staleAfter + ' s';
  watching = s.watching || [];
  scorecards = s.scorecards || [];
  showScorecards();
  const seen = new Set();
  for (const t of s.logs) {
    seen.add(t.log);
    if ((answered.get(t.log) || 0) > request) continue;
    answered.set(t.log, request);
    const before = logs.get(t.log);
    logs.set(t.log, t);
    if (before && before.state !== t.state && (t.state === 'warning' || t.state === 'violation')) alert(t);
    else if (before && worstState(before) !== worstState(t) && ['violated', 'warning'].includes(t.worst.state)) {
      alert(t);
    }
  }
  if (full) {
    for (const log of [...logs.keys()]) if (!seen.has(log)) logs.delete(log);
  }
  show();
}

function connection(state, text) {
  const c = document.getElementById('connection');
  c.dataset.state = state;
  c.textContent = text;
}

async function refresh(log) {
  const request = ++requests;
  try {
    const r = await fetch(log === undefined ? '/status' : '/status?log=' + encodeURIComponent(log), {cache: 'no-store'});
    if (!r.ok) throw new Error('status ' + r.status);
    apply(await r.json(), log === undefined, request);
  } catch (e) {
    connection('lost', 'server unreachable: showing the last state');
  }
}

function flush() {
  flushTimer = null;
  const batch = [...pending];
  pending.clear();
  if (batch.length > 8) refresh(); else batch.forEach(refresh);
}

// The page arrives with the state it was served with, so it shows the tiles before any request of its own.
switches();
document.getElementById('view').textContent = view === 'compact' ? 'show tiles' : 'compact view';
const initial = document.getElementById('initial-status');
if (initial && initial.textContent.trim().startsWith('{')) apply(JSON.parse(initial.textContent), true, ++requests);

const events = new EventSource('/events');
events.onopen = () => { connection('live', 'live'); refresh(); };
events.onerror = () => connection('lost', 'reconnecting\u2026');
events.onmessage = (m) => {
  pending.add(JSON.parse(m.data).log);
  if (!flushTimer) flushTimer = setTimeout(flush, 50);
};
// Readings and staleness change without events: a full refresh every second (every 5 s for a big fleet).
(function tick() {
  refresh().finally(() => setTimeout(tick, logs.size > 20 ? 5000 : 1000));
})();
