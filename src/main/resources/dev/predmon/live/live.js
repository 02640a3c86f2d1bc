// predmon live view: one tile per watched log, kept up to date from /status, refreshed at once when /events says
// that a log has news. Hand-written, no library, nothing fetched from elsewhere. Text from logs goes into the page
// through textContent only.
'use strict';
(() => {
  const SVG = 'http://www.w3.org/2000/svg';
  const tilesEl = document.getElementById('tiles');
  const tiles = new Map(); // log -> <article>
  const pending = new Set();
  let flushTimer = null;
  let lastLogs = [];

  function el(tag, cls, text) {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined && text !== null) e.textContent = text;
    return e;
  }

  function svg(tag, attrs, text) {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  const num = (x, digits) => (x === null || x === undefined) ? '?' : Number(x).toFixed(digits);
  const at = (t, unit) => unit === 'ticks' ? 'tick ' + num(t, 0) : 't=' + num(t, 2);
  const span = (d, unit) => unit === 'ticks' ? num(d, 0) + ' ticks' : num(d, 2) + ' s';
  const pct = (b) => (b === null || b === undefined) ? 'unknown' : num(b, 1) + '%';
  // The file's name, with its directory when that is short (robots/r1/monitor.log: r1/monitor.log); the full path
  // is the title.
  const shortName = (log) => {
    const parts = log.split(/[\\/]/).filter(p => p.length > 0);
    const dir = parts.length > 1 ? parts[parts.length - 2] : '';
    return dir && dir.length <= 16 ? dir + '/' + parts[parts.length - 1] : parts[parts.length - 1];
  };

  function verdict(t) {
    if (t.light === 'red') {
      return 'VIOLATED at ' + at(t.violation.time, t.unit) + ' (' + pct(t.violation.battery) + ')'
        + (t.warning ? ', predicted' : ', not predicted');
    }
    if (t.light === 'yellow') {
      return 'WARNING: the run can only be faulty scenario ' + t.warning.scenarios.join(', ');
    }
    if (t.light === 'green') {
      return t.noMatch ? 'held; no learned scenario matches this run' : 'held; no faulty prediction';
    }
    return t.records === 0 ? 'no data yet: waiting for the log' : 'no data yet';
  }

  function eventText(e, unit) {
    const u = e.unit || unit;
    const where = (e.time !== undefined ? at(e.time, u) + ' ' : '') + (e.line !== undefined ? 'line ' + e.line + ': ' : '');
    switch (e.event) {
      case 'eliminated':
        return where + 'model ' + e.model + ' (' + (e.faulty ? 'faulty' : 'nominal') + ') eliminated: ' + e.reason;
      case 'warning':
        return where + 'WARNING: only ' + e.scenarios.join(', ') + ' left; battery ' + pct(e.battery);
      case 'violation':
        return where + 'VIOLATION of ' + e.property + ': ' + pct(e.battery);
      case 'no-match':
        return where + 'no learned scenario matches this run any more';
      case 'run':
        return where + 'run ' + e.run + ' begins: every model starts over';
      case 'restarted':
        return 'log ' + e.reason + ': monitoring starts over';
      default:
        return where + e.event;
    }
  }

  function plot(t) {
    const W = 440, H = 150, L = 36, R = 10, T = 14, B = 20;
    const s = svg('svg', {class: 'plot', viewBox: '0 0 ' + W + ' ' + H, role: 'img',
      'aria-label': 'battery over time in run ' + t.run});
    s.appendChild(svg('rect', {class: 'frame', x: L, y: T, width: W - L - R, height: H - T - B}));
    const pts = t.series;
    const times = pts.map(p => p[0]);
    if (t.warning) times.push(t.warning.time);
    if (t.violation) times.push(t.violation.time);
    if (times.length === 0) {
      s.appendChild(svg('text', {class: 'empty', x: L + 10, y: T + 24}, 'no reading of the property yet'));
      return s;
    }
    let t0 = Math.min(...times), t1 = Math.max(...times);
    if (t1 - t0 < 1e-9) t1 = t0 + 1;
    const values = pts.map(p => p[1]);
    const lo = Math.min(0, ...values), hi = Math.max(100, ...values);
    const x = (tv) => L + (tv - t0) / (t1 - t0) * (W - L - R);
    const y = (v) => T + (hi - v) / (hi - lo) * (H - T - B);
    for (const g of [0, 25, 50, 75, 100]) {
      if (g < lo || g > hi) continue;
      s.appendChild(svg('line', {class: 'grid', x1: L, x2: W - R, y1: y(g), y2: y(g)}));
      s.appendChild(svg('text', {class: 'axis', x: L - 4, y: y(g) + 3, 'text-anchor': 'end'}, String(g)));
    }
    if (t.threshold !== undefined && t.threshold !== null) {
      s.appendChild(svg('line', {class: 'threshold', x1: L, x2: W - R, y1: y(t.threshold), y2: y(t.threshold)}));
    }
    if (pts.length > 0) {
      s.appendChild(svg('polyline', {class: 'battery',
        points: pts.map(p => x(p[0]).toFixed(1) + ',' + y(p[1]).toFixed(1)).join(' ')}));
    }
    const mark = (time, kind, label, anchorRight, y0) => {
      const right = anchorRight || x(time) > W - R - 50; // a label that would leave the plot goes left of its line
      s.appendChild(svg('line', {class: 'mark-' + kind, x1: x(time), x2: x(time), y1: T, y2: H - B}));
      s.appendChild(svg('text', {class: 'label-' + kind, x: x(time) + (right ? -3 : 3), y: y0,
        'text-anchor': right ? 'end' : 'start'}, label));
    };
    if (t.warning) mark(t.warning.time, 'warning', 'warning', !!t.violation, T - 3);
    if (t.violation) {
      // Close to the warning's mark, its label goes one line lower so that the two do not overlap.
      const close = t.warning && Math.abs(x(t.violation.time) - x(t.warning.time)) < 60;
      mark(t.violation.time, 'violation', 'violation', false, close ? T + 10 : T - 3);
    }
    const unit = t.unit === 'ticks' ? ' ticks' : ' s';
    s.appendChild(svg('text', {class: 'axis', x: L, y: H - 5}, num(t0, 1) + unit));
    s.appendChild(svg('text', {class: 'axis', x: W - R, y: H - 5, 'text-anchor': 'end'}, num(t1, 1) + unit));
    return s;
  }

  function render(t) {
    let tile = tiles.get(t.log);
    if (!tile) {
      tile = el('article', 'tile');
      tile.dataset.log = t.log;
      tiles.set(t.log, tile);
      tilesEl.appendChild(tile);
    }
    tile.dataset.light = t.light;
    tile.dataset.stale = String(t.stale);
    tile.dataset.run = String(t.run);

    const head = el('header');
    const h2 = el('h2', null, shortName(t.log));
    h2.title = t.log;
    head.append(h2, el('span', 'run', 'run ' + t.run));
    if (t.stale) head.append(el('span', 'badge stale', 'STALE ' + num(t.quietSeconds, 0) + ' s'));

    const status = el('div', 'status');
    const light = el('span', 'light ' + t.light);
    light.setAttribute('role', 'img');
    light.setAttribute('aria-label', t.light);
    const words = el('div');
    words.append(el('div', 'property', t.property || 'prediction'), el('div', 'verdict', verdict(t)));
    status.append(light, words, el('div', 'battery-now', t.battery === null ? '' : pct(t.battery)));

    const lead = el('p', t.lead === null ? 'lead none' : 'lead');
    if (t.lead !== null) {
      lead.textContent = 'lead ' + span(t.lead, t.unit) + ': warning at ' + pct(t.warning.battery)
        + ', violation at ' + pct(t.violation.battery);
    }

    const models = el('section', 'models');
    const alive = t.models.filter(m => m.alive).length;
    models.append(el('h3', null, 'models: ' + alive + ' of ' + t.models.length + ' still match'));
    const ml = el('ul');
    for (const m of t.models) {
      const li = el('li', m.alive ? 'alive' : 'gone');
      li.append(el('span', 'id', m.model), el('small', null, ' ' + (m.faulty ? 'faulty' : 'nominal')
        + (m.alive ? '' : ' \u2014 ' + m.reason)));
      if (!m.alive) li.title = m.reason;
      ml.appendChild(li);
    }
    models.appendChild(ml);

    const events = el('section', 'events');
    events.appendChild(el('h3', null, 'last events'));
    const ol = el('ol');
    for (const e of t.events.slice().reverse()) {
      const li = el('li', e.event, eventText(e, t.unit));
      li.title = li.textContent;
      ol.appendChild(li);
    }
    if (t.events.length === 0) ol.appendChild(el('li', null, 'none yet'));
    events.appendChild(ol);

    const parts = [head, status, lead, plot(t), models, events];
    if (t.earlierRuns.length > 0) {
      const runs = el('section', 'runs');
      runs.appendChild(el('h3', null, 'earlier runs'));
      const ul = el('ul');
      if (t.earlierRunsOmitted > 0) ul.appendChild(el('li', null, t.earlierRunsOmitted + ' earlier not shown'));
      for (const r of t.earlierRuns) {
        const li = el('li');
        li.append(el('span', 'light ' + r.light), 'run ' + r.run + ' (line ' + r.line + '): '
          + (r.warning ? 'warned' : 'no warning') + ', ' + (r.violation ? 'violated' : 'held')
          + (r.lead !== null ? ', lead ' + span(r.lead, t.unit) : '') + (r.noMatch ? ', no match' : ''));
        ul.appendChild(li);
      }
      runs.appendChild(ul);
      parts.push(runs);
    }
    parts.push(el('footer', null, t.records + ' records, line ' + t.line + ' \u00b7 log grew '
      + num(t.quietSeconds, 1) + ' s ago'));
    tile.replaceChildren(...parts);
  }

  function summary() {
    const count = (light) => lastLogs.filter(t => t.light === light).length;
    const stale = lastLogs.filter(t => t.stale).length;
    document.getElementById('summary').textContent = lastLogs.length + (lastLogs.length === 1 ? ' log: ' : ' logs: ')
      + ['red', 'yellow', 'green', 'grey'].map(l => count(l) + ' ' + l).join(', ') + (stale ? '; ' + stale + ' stale' : '');
  }

  function connection(state, text) {
    const c = document.getElementById('connection');
    c.dataset.state = state;
    c.textContent = text;
  }

  function apply(s) {
    document.getElementById('stale-after').textContent = s.staleAfter + ' s';
    for (const t of s.logs) {
      render(t);
      const i = lastLogs.findIndex(x => x.log === t.log);
      if (i >= 0) lastLogs[i] = t; else lastLogs.push(t);
    }
    summary();
  }

  async function load(log) {
    const r = await fetch(log === undefined ? '/status' : '/status?log=' + encodeURIComponent(log), {cache: 'no-store'});
    if (!r.ok) throw new Error('status ' + r.status);
    apply(await r.json());
  }

  async function refresh(log) {
    try {
      await load(log);
    } catch (e) {
      connection('lost', 'server unreachable: showing the last state');
    }
  }

  function flush() {
    flushTimer = null;
    const logs = [...pending];
    pending.clear();
    if (logs.length > 8) refresh(); else logs.forEach(refresh);
  }

  // The page arrives with the state it was served with, so it shows the tiles before any request of its own.
  const initial = document.getElementById('initial-status');
  if (initial && initial.textContent.trim().startsWith('{')) apply(JSON.parse(initial.textContent));

  const events = new EventSource('/events');
  events.onopen = () => { connection('live', 'live'); refresh(); };
  events.onerror = () => connection('lost', 'reconnecting\u2026');
  events.onmessage = (m) => {
    const e = JSON.parse(m.data);
    pending.add(e.log);
    if (!flushTimer) flushTimer = setTimeout(flush, 50);
  };
  // Readings and staleness change without events: a full refresh every second (every 5 s for a big fleet).
  (function tick() {
    refresh().finally(() => setTimeout(tick, lastLogs.length > 20 ? 5000 : 1000));
  })();
})();
