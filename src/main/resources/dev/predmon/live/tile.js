// predmon live view: a tile (the full view) and a row (the compact view) of one robot. Text from logs goes into the
// page through textContent only.
'use strict';
import {GLYPHS, PROPERTY_GLYPHS, PROPERTY_STATES, PROPERTY_WORDS, STATE_WORDS, alarmOf, isOwn, ownProperty, at, basisWords, chance, distanceWords, earlierText, eventText, forecastWords, momentText,
  num, own, pct, propertyForecast, recoveryWords, shortSpan, verdict, whenWords} from './words.js';
import {plot} from './plot.js';

export function el(tag, cls, text) {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  if (text !== undefined && text !== null) e.textContent = text;
  return e;
}

/** States that ask for someone's attention: they can be acknowledged, and a warning or violation alerts. */
export const NEEDS_ATTENTION = new Set(['violation', 'warning', 'unknown', 'no-verdict']);

/** A robot's light: its worst property's, as /status gives it (the forecast property's own is in the list). */
function light(t, small) {
  const l = el('span', 'light ' + t.light + (small ? ' small' : ''), GLYPHS[t.state] || '');
  l.setAttribute('role', 'img');
  l.setAttribute('aria-label', STATE_WORDS[t.state] || t.state);
  return l;
}

/** A property's light: its colour and glyph, its state in words for a screen reader. */
export function propertyLight(p) {
  const l = el('span', 'light small ' + p.light, PROPERTY_GLYPHS[p.state] || '');
  l.setAttribute('role', 'img');
  l.setAttribute('aria-label', p.property + ' ' + (PROPERTY_WORDS[p.state] || p.state));
  return l;
}

/** One light per property, worst first: its id and name, its verdict in words, its forecast or that it has none. */
function propertyList(t) {
  const ul = el('ul', 'props');
  for (const p of t.properties || []) {
    const li = el('li', 'prop ' + p.state);
    li.dataset.property = p.property;
    li.dataset.state = p.state;
    const head = el('div', 'prop-head');
    head.append(el('b', 'prop-id', p.property), el('span', 'prop-name', p.name));
    const text = el('div', 'prop-text');
    text.append(head, el('div', 'prop-words', p.words), el('div', 'prop-forecast', propertyForecast(p, t)));
    if (p.recovery) text.append(el('div', 'prop-recovery', 'recovered: ' + p.recovery));
    if (p.action && (p.state === 'warning' || p.state === 'violated') && !isOwn(p, t)) {
      const a = el('div', 'prop-action');
      a.append(el('b', null, 'Do now: '), p.action);
      text.append(a);
    }
    li.append(propertyLight(p), text);
    ul.appendChild(li);
  }
  return ul;
}

/** The light a robot shows: its worst property's, which /status gives as the robot's. */
export function shownLight(t) {
  return t.light;
}

/** The robot's state as the page counts and sorts it: its worst property's, as /status gives it. */
export function shownState(t) {
  return t.state;
}

/**
 * The compact view's chip of the worst property beside the forecast's (whose light is the row's own): its light and
 * id when it is violated, warned or unknown, its light alone when the others are well; every property's words in
 * the tooltip.
 */
function worstChip(t) {
  const others = (t.properties || []).filter(p => !isOwn(p, t));
  if (others.length === 0) return null;
  const w = others[0];
  const chip = el('span', 'worst');
  chip.dataset.state = w.state;
  chip.dataset.property = w.property;
  const calm = w.state === 'holds' || w.state === 'pending' || w.state === 'no-evidence';
  // the others all well: their light alone, so that the robot's name keeps the room; the tooltip says which
  chip.append(propertyLight(w));
  if (!calm) chip.append(el('span', 'worst-text', w.property));
  chip.title = (t.properties || []).map(p => p.property + ' (' + PROPERTY_WORDS[p.state] + '): ' + p.words + ' \u2014 '
    + propertyForecast(p, t)).join('\n');
  return chip;
}

function ackButton(t, ui, compact) {
  if (!NEEDS_ATTENTION.has(shownState(t)) && !t.stale) return null;
  const acked = ui.acked(t);
  const b = el('button', 'ack', compact ? (acked ? 'acked' : 'ack') : acked ? 'acknowledged' : 'acknowledge');
  b.type = 'button';
  b.setAttribute('aria-pressed', String(acked));
  b.title = acked ? 'silenced until this robot\u2019s state changes; click to undo'
    : 'silence this robot until its state changes (this browser only)';
  // On press, not on release: the page redraws every second, and a click whose button was redrawn in between
  // would be lost. A key (Enter, Space) gives a click of detail 0.
  const act = (ev) => {
    ev.stopPropagation();
    ev.preventDefault();
    ui.acknowledge(t, !acked);
  };
  b.addEventListener('pointerdown', act);
  b.addEventListener('click', (ev) => {
    ev.stopPropagation();
    if (ev.detail === 0) act(ev);
  });
  return b;
}

function badges(t, compact) {
  const out = [];
  if (own(t) === 'ended' && !compact) out.push(el('span', 'badge ended', 'RUN ENDED'));
  if (t.stale) {
    const b = el('span', 'badge stale', 'STALE' + (compact ? '' : ' ' + num(t.quietSeconds, 0) + ' s'));
    b.title = 'the log has not grown for ' + num(t.quietSeconds, 0) + ' s'
      + (t.running.length ? ' while ' + t.running.join(', ') + ' was running' : '');
    out.push(b);
  }
  return out;
}

/** What to do, when something is to be done: or that the robot already does it. */
function actionLine(t) {
  if (!t.action || (own(t) !== 'warning' && own(t) !== 'violation')) return null;
  if (t.underWay) {
    const p = el('p', 'action under-way');
    p.append(el('b', null, 'Under way since ' + at(t.underWay.since, t.unit) + ': '), t.action);
    p.title = 'the robot already does it: ' + t.underWay.by + ' (line ' + t.underWay.line + ')';
    return p;
  }
  const p = el('p', 'action');
  p.append(el('b', null, 'Do now: '), t.action);
  return p;
}

/**
 * The forecast: in a warning, the chance of a violation and when; below the threshold, how far the run is from a
 * warning, with no countdown to a violation that is not expected.
 */
function forecastLine(t, ui) {
  const f = t.forecast;
  const state = own(t);
  if (!f || state === 'ended' || state === 'violation' || state === 'no-verdict') return null;
  const p = el('div', 'forecast');
  p.title = f.explanation || '';
  if (ui.noSkill(t)) {
    // no headline: the number would look like knowledge the models showed they lack
    p.append(el('span', 'noskill', 'the forecast has no skill on these models'),
      el('small', 'basis', 'it did no better than the base rate in cross-validation; it says '
        + chance(f.probability) + ', ' + whenWords(f)));
    return p;
  }
  const distance = state !== 'warning' ? distanceWords(f, t.warnsAt) : null;
  // among several properties, the forecast says whose it is
  const mine = (t.properties || []).length > 1 ? ownProperty(t) : null;
  if (mine) p.append(el('span', 'forecast-of', mine.property + ': '));
  if (distance) {
    p.append(el('span', 'chance distance', distance), el('small', 'basis', basisWords(f)));
  } else {
    p.append(el('span', 'chance', chance(f.probability)), el('span', 'when', ' chance of a violation, '
      + whenWords(f)), el('small', 'basis', basisWords(f)));
  }
  return p;
}

/** How the run recovered from its last alarm. */
function recoveryLine(t) {
  if (own(t) !== 'ok' || !t.recovered) return null;
  return el('p', 'recovery', recoveryWords(t));
}

/** Why the monitor warned, in its words (which rule, what the forecast rests on). */
function whyLine(t) {
  if (own(t) !== 'warning' || !t.warning || !t.warning.reason) return null;
  const p = el('p', 'why');
  p.append(el('b', null, 'Why: '), t.warning.reason);
  return p;
}

function details(key, ui, summary, body) {
  const d = el('details', key);
  d.open = ui.isOpen(key, d);
  d.addEventListener('toggle', () => ui.setOpen(key, d.open));
  d.append(el('summary', null, summary), body);
  return d;
}

/** The tile of {@code t}, into {@code tile} (an article that keeps its place on the page). */
export function renderTile(tile, t, ui) {
  const head = el('header');
  const h2 = el('h2', null, t.name);
  h2.title = t.log;
  head.append(light(t), h2, el('span', 'run', 'run ' + t.run), ...badges(t));
  const ack = ackButton(t, ui);
  if (ack) head.append(ack);

  // The headline is the worst property's; the big number is the forecast property's value, named, one property
  // among the others.
  const status = el('div', 'status');
  const words = el('div', 'words');
  const alarm = alarmOf(t);
  words.append(el('div', 'property', alarm ? alarm.name : t.property || 'prediction'), el('div', 'verdict', verdict(t)));
  const big = el('div', 'value-now');
  const mine = ownProperty(t);
  if (t.value !== null) {
    if (mine && (t.properties || []).length > 1) big.append(el('small', 'value-of', mine.property));
    big.append(pct(t.value, t.threshold));
  }
  status.append(words, big);

  const lead = el('p', t.lead === null ? 'lead none' : 'lead');
  if (t.lead !== null) {
    lead.textContent = 'lead ' + (t.unit === 'ticks' ? num(t.lead, 0) + ' ticks' : num(t.lead, 2) + ' s')
      + ': warning at ' + pct(t.warning.value, t.threshold) + ', violation at '
      + pct(t.violation.value, t.threshold);
  }
  const parts = [head, status, propertyList(t)];
  for (const p of [actionLine(t), forecastLine(t, ui), whyLine(t), recoveryLine(t)]) if (p) parts.push(p);
  if (own(t) !== 'no-verdict') parts.push(lead);
  if (t.history.length > 0) {
    const h = el('p', 'history');
    h.append(el('b', null, 'this run: '), t.history.map(m => momentText(m, t)).join(' \u2192 '));
    parts.push(h);
  }
  parts.push(plot(t));

  const alive = t.models.filter(m => m.alive).length;
  const ml = el('ul');
  for (const m of t.models) {
    const li = el('li', m.alive ? 'alive' : 'gone');
    li.append(el('span', 'id', m.model), el('small', null, ' ' + (m.faulty ? 'faulty' : 'nominal')
      + (m.alive ? '' : ' \u2014 ' + m.reason)));
    ml.appendChild(li);
  }
  parts.push(details('models', ui, 'models: ' + alive + ' of ' + t.models.length + ' still match', ml));

  const ol = el('ol');
  for (const e of t.events.slice().reverse()) ol.appendChild(el('li', e.event, eventText(e, t)));
  if (t.events.length === 0) ol.appendChild(el('li', null, 'none yet'));
  const events = el('section', 'events');
  events.append(el('h3', null, 'last events'), ol);
  parts.push(events);

  if (t.earlierRuns.length > 0) {
    const ul = el('ul');
    if (t.earlierRunsOmitted > 0) ul.appendChild(el('li', null, t.earlierRunsOmitted + ' earlier not shown'));
    for (const r of t.earlierRuns) {
      const li = el('li');
      li.append(el('span', 'light small ' + r.light), earlierText(r, t.unit,
        (ownProperty(t) || {}).property));
      ul.appendChild(li);
    }
    const runs = el('section', 'runs');
    runs.append(el('h3', null, 'earlier runs'), ul);
    parts.push(runs);
  }
  parts.push(el('footer', null, t.log + ' \u00b7 ' + (t.exists === false ? 'no such file yet'
    : t.records + ' records, line ' + t.line + ' \u00b7 ' + (typeof t.deleted === 'number'
      ? 'log deleted; leaves the page in ' + num(t.leavesIn / 60, 0) + ' min'
      : 'log grew ' + num(t.quietSeconds, 1) + ' s ago'))));
  if (ui.single) {
    // One robot alone uses the screen: its words beside a large plot.
    const plotEl = parts.find(p => p.tagName === 'svg');
    const words = el('div', 'single-words');
    words.append(...parts.filter(p => p !== head && p !== plotEl));
    const body = el('div', 'single-body');
    body.append(words, plotEl);
    tile.replaceChildren(head, body);
  } else {
    tile.replaceChildren(...parts);
  }
}

/** The second line of a compact row: the state and what matters most about it. */
function rowWords(t, ui) {
  const f = ui.noSkill(t) ? null : t.forecast; // a forecast without skill is no headline here either
  const state = STATE_WORDS[own(t)] || own(t);
  switch (own(t)) {
    case 'violation':
      return state + ' since ' + at(t.violation.time, t.unit) + todo(t);
    case 'warning':
      return state + (f ? ' ' + chance(f.probability) + (f.timeToViolation === null ? ''
        : ' ~' + shortSpan(f.timeToViolation, f.unit)) : '') + todo(t);
    case 'no-verdict':
      return state + ' \u00b7 ' + t.noVerdict;
    case 'unknown':
      return state + (t.noMatch ? ' \u00b7 no model matches' : ' \u00b7 new behaviour')
        + (f ? ' \u00b7 ' + chance(f.probability) : '');
    case 'ok':
      return (t.recovered ? 'OK, recovered ' + at(t.recovery.time, t.unit) : state)
        + (f ? ' \u00b7 ' + (distanceWords(f, t.warnsAt) || chance(f.probability)) : '');
    default:
      return own(t) === 'ended' ? state : t.exists === false ? 'no such file yet' : 'waiting for data';
  }
}

/** What to do, or that it is under way, after an arrow. */
function todo(t) {
  if (!t.action) return '';
  return t.underWay ? ' \u2192 under way since ' + at(t.underWay.since, t.unit) : ' \u2192 ' + t.action;
}

/** The compact row of {@code t}: one light per property, the robot, its value and the state in a few words. */
export function renderRow(row, t, ui) {
  const name = el('span', 'name', t.name);
  name.title = t.log;
  const line1 = el('div', 'line1');
  const chip = worstChip(t);
  line1.append(name, ...badges(t, true), ...(chip ? [chip] : []), el('span', 'value', t.value === null ? '' : pct(t.value, t.threshold)));
  // another property's alarm first: which, and what to do
  const w = alarmOf(t);
  const alarm = w ? w.property + ' ' + PROPERTY_WORDS[w.state].toUpperCase() + (w.action ? ' \u2192 ' + w.action : '')
    + ' \u00b7 ' : '';
  const line2 = el('div', 'line2', alarm + rowWords(t, ui));
  line2.title = verdict(t) + (forecastWords(t.forecast) ? '\n' + forecastWords(t.forecast) : '');
  const text = el('div', 'text');
  text.append(line1, line2);
  const parts = [light(t, true), text];
  const ack = ackButton(t, ui, true);
  if (ack) parts.push(ack);
  row.replaceChildren(...parts);
  row.title = 'show ' + t.name + ' in full';
}
