// predmon live view: a tile's data in an operator's words. No DOM here.
'use strict';

/** The states worst first, as the page sorts them, with their names on the page. */
export const STATES = ['violation', 'warning', 'unknown', 'no-verdict', 'ok', 'waiting', 'ended'];
export const STATE_WORDS = {violation: 'VIOLATION', warning: 'WARNING', unknown: 'UNKNOWN', 'no-verdict': 'NO VERDICT',
  ok: 'OK', waiting: 'WAITING', ended: 'RUN ENDED'};
/** A glyph on each light, so that the state does not rest on colour alone. */
export const GLYPHS = {violation: '\u2715', warning: '!', unknown: '?', 'no-verdict': '\u2298', ok: '\u2713',
  waiting: '\u2026', ended: '\u25A0'};

/** A property's light, worst first, with its glyph and its name on the page. */
export const PROPERTY_STATES = ['violated', 'warning', 'unknown', 'no-evidence', 'pending', 'holds'];
export const PROPERTY_GLYPHS = {violated: '\u2715', warning: '!', unknown: '?', 'no-evidence': '\u2205',
  pending: '\u2026', holds: '\u2713'};
export const PROPERTY_WORDS = {violated: 'violated', warning: 'warning', unknown: 'unknown',
  'no-evidence': 'no evidence', pending: 'pending', holds: 'holds'};

const missing = (x) => x === null || x === undefined || Number.isNaN(x);

/**
 * The forecast property's own state (the robot's {@code state} is its worst property's): what the forecast's words,
 * its value, its warning and its violation are about.
 */
export const own = (t) => t.forecastState || t.state;

/**
 * The forecast's own property, whose value, chart and words the tile's headline shows: the one whose id the log's
 * status names ({@code t.propertyId}), or null when it names none. Several properties may have a forecast (bounds,
 * absences) and two may share a name, so neither a forecast nor a name says which one it is.
 */
export function ownProperty(t) {
  if (!t.propertyId) return null;
  return (t.properties || []).find(p => p.property === t.propertyId) || null;
}

/** Whether {@code p} (a property of {@code t}, or its worst) is the forecast's own property. */
export function isOwn(p, t) {
  return !!p && !!t.propertyId && p.property === t.propertyId;
}

/** The worst property when it is not the forecast's and is violated or warned: the tile's headline, or null. */
export function alarmOf(t) {
  const w = t.worst;
  return w && !isOwn(w, t) && (w.state === 'violated' || w.state === 'warning') ? w : null;
}

export const num = (x, digits) => missing(x) ? '?' : Number(x).toFixed(digits);

/**
 * A value of the property with two decimals. Below the threshold it is rounded down, so that a violating 19.995
 * never reads as the threshold itself.
 */
export function value(x, threshold) {
  if (missing(x)) return '?';
  const v = Number(x);
  if (!missing(threshold) && v < threshold) return (Math.floor(v * 100) / 100).toFixed(2);
  return v.toFixed(2);
}

export const pct = (x, threshold) => missing(x) ? 'unknown' : value(x, threshold) + '%';

/** A point in the log's time: t=27.91 s, or tick 188. */
export const at = (t, unit) => unit === 'ticks' ? 'tick ' + num(t, 0) : 't=' + num(t, 2) + ' s';

/** A duration: 5.0 s, 48 ticks. */
export function span(d, unit) {
  if (missing(d)) return '?';
  if (unit === 'ticks') return num(d, 0) + ' ticks';
  return (Math.abs(d) >= 100 ? num(d, 0) : Math.abs(d) >= 10 ? num(d, 1) : num(d, 2)) + ' s';
}

/** A duration in few characters, for the compact view: 6.5 s, 48 s, 48 ticks. */
export function shortSpan(d, unit) {
  if (missing(d)) return '?';
  return unit === 'ticks' ? num(d, 0) + ' ticks' : (Math.abs(d) >= 10 ? num(d, 0) : num(d, 1)) + ' s';
}

/** The probability of a violation in this run: 98%, or <1% / >99% at the ends. */
export function chance(p) {
  if (missing(p)) return '?';
  const v = Math.round(p * 100);
  if (p > 0 && v === 0) return '<1%';
  if (p < 1 && v === 100) return '>99%';
  return v + '%';
}

/** When the violation comes, if it does: "in about 5.0 s (4.8-5.4 s)", or "no violation in sight". */
export function whenWords(f) {
  if (!f || missing(f.timeToViolation)) return 'no violation in sight';
  const u = f.unit;
  const range = missing(f.low) ? '' : missing(f.high) ? ' (' + span(f.low, u) + ' or more)'
    : ' (' + span(f.low, u) + '\u2013' + span(f.high, u) + ')';
  return 'in about ' + span(f.timeToViolation, u) + range;
}

/** What the forecast rests on, for an operator. */
export function basisWords(f) {
  if (!f) return '';
  const runs = f.violated + ' of ' + f.runs + ' training runs';
  switch (f.basis) {
    case 'matched':
      return 'matched: of ' + f.runs + ' training runs that were where this run is now, ' + f.violated + ' went on to violate';
    case 'resynchronised':
      return 'new behaviour since line ' + f.novelSince + '; matched again on the latest steps: ' + runs
        + ' violated';
    case 'value only':
      return 'nothing learned fits' + (missing(f.novelSince) ? '' : ' since line ' + f.novelSince)
        + ': from the value alone, ' + runs + ' that went this low violated';
    case 'violated':
      return 'the property is violated';
    default:
      return f.basis;
  }
}

/** The forecast on one line: "98% chance of a violation, in about 5.0 s (4.8-5.4 s)". */
export function forecastWords(f) {
  if (!f) return null;
  if (f.basis === 'violated') return 'violated';
  return chance(f.probability) + ' chance of a violation, ' + whenWords(f);
}

/** How far a run below the warning threshold is from a warning: "P 0.23, warning at 0.86". */
export function distanceWords(f, warnsAt) {
  if (!f || missing(warnsAt) || f.basis === 'violated') return null;
  return 'P ' + num(f.probability, 2) + ', warning at ' + num(warnsAt, 2);
}

/** Which clause of the rule warned, in a headline. */
function warningWords(t) {
  const w = t.warning;
  switch (w.clause) {
    case 'matching':
      return 'WARNING: the run can only be faulty' + (w.scenarios.length ? ' scenario ' + w.scenarios.join(', ') : '')
        + ' (the matching)';
    case 'novelty':
      return 'WARNING: new behaviour, below every safe run (the value is lower than any training run that held went)';
    default:
      return 'WARNING: the forecast predicts a violation' + (w.forecast && !missing(t.warnsAt)
        ? ' (P ' + num(w.forecast.probability, 2) + ', warning at ' + num(t.warnsAt, 2) + ')' : '');
  }
}

/** The recovery in words: "recovered at tick 154: ...". */
export function recoveryWords(t) {
  const r = t.recovery;
  if (!r) return null;
  return 'recovered ' + at(r.time, t.unit) + ' (' + pct(r.value, t.threshold) + '): ' + r.reason;
}

/**
 * The state in a sentence, worst property first: another property violated or warned says so with its words; else
 * what holds now of the forecast's property, and why.
 */
export function verdict(t) {
  const w = alarmOf(t);
  if (w) {
    return w.state === 'violated'
      ? 'VIOLATED: ' + w.property + ' \u2014 ' + (w.what ? 'line ' + w.line + ': ' + w.what : w.words)
      : 'WARNING: ' + w.property + ' \u2014 ' + w.words;
  }
  return ownVerdict(t);
}

/** The forecast property's state in a sentence. */
function ownVerdict(t) {
  const thr = t.threshold;
  const others = (t.properties || []).length > 1;
  switch (own(t)) {
    case 'violation':
      return 'VIOLATED since ' + at(t.violation.time, t.unit) + ' (' + pct(t.violation.value, thr) + ')'
        + (t.warning ? ', predicted ' + span(t.lead, t.unit) + ' ahead' : ', not predicted');
    case 'warning':
      return warningWords(t);
    case 'unknown':
      return 'UNKNOWN: ' + unknownWhy(t);
    case 'no-verdict':
      return 'NO VERDICT: ' + t.noVerdict;
    case 'ok':
      if (t.recovered) {
        return 'RECOVERED: ' + (t.recovery.cause === 'property' ? 'the property holds again (' + pct(t.value, thr)
          + '); violated at ' + at(t.violation.time, t.unit) + ' (' + pct(t.violation.value, thr) + ')'
          : 'the warning\u2019s cause ended ' + at(t.recovery.time, t.unit) + ' (' + pct(t.recovery.value, thr)
            + ')' + (t.recovery.cause === 'action' ? ', by the action' : ''));
      }
      return others ? 'OK: every property holds and no warning is raised'
        : 'OK: the property holds and no warning is raised';
    case 'ended':
      return 'Run ended: ' + runOutcome(t);
    default:
      return t.records > 0 ? 'waiting for a reading of the property'
        : t.exists === false ? 'waiting for the log: no such file yet' : 'waiting for the log\u2019s first record';
  }
}

function unknownWhy(t) {
  const f = t.forecast;
  if (t.noMatch) {
    return 'no learned scenario matches this run since line ' + t.noMatchLine
      + (f ? '; the forecast rests on ' + (f.basis === 'value only' ? 'the value alone' : 'the latest steps') : '');
  }
  if (f && f.basis === 'value only') return 'nothing learned fits the latest steps; the forecast rests on the value alone';
  if (f && !missing(f.novelSince)) return 'the run does something no training run did, since line ' + f.novelSince;
  return 'the models cannot judge this run';
}

/**
 * How a run ended, worst first: every other property it violated, in its own words, then the forecast's property
 * (named when there are others), its warning and whether any model matched.
 */
function runOutcome(t) {
  const thr = t.threshold;
  const parts = [];
  const props = t.properties || [];
  for (const p of props) {
    if (!isOwn(p, t) && p.state === 'violated') parts.push(p.property + ' ' + p.words);
  }
  const own = props.length > 1 ? ownProperty(t) : null;
  const name = own ? own.property + ' ' : 'the property ';
  parts.push(t.violation ? name + 'violated at ' + at(t.violation.time, t.unit) + ' (' + pct(t.violation.value, thr)
    + ')' : name + 'held' + (t.value === null ? '' : ' (last ' + pct(t.value, thr) + ')'));
  if (t.warning) parts.push('warned at ' + at(t.warning.time, t.unit));
  if (t.noMatch) parts.push('no model matched');
  return parts.join(', ');
}

/** The last events, one line each. */
export function eventText(e, t) {
  const u = e.unit || t.unit;
  const thr = t.threshold;
  const where = (e.time !== undefined ? at(e.time, u) + ' ' : '') + (e.line !== undefined ? 'line ' + e.line + ': ' : '');
  switch (e.event) {
    case 'eliminated':
      return where + 'model ' + e.model + ' (' + (e.faulty ? 'faulty' : 'nominal') + ') eliminated: ' + e.reason;
    case 'warning':
      // another property's warning (or one without a value: a deadline's, an absence's) in its own words
      if (e.clause === 'deadline' || missing(e.value) || (e.property && e.property !== t.propertyId)) {
        return where + 'WARNING of ' + e.property + ': ' + (e.reason || '').split(';')[0];
      }
      // The reason's first clause: the whole of it is under the tile's verdict.
      return where + 'WARNING at ' + pct(e.value, thr) + ': '
        + (e.reason ? e.reason.split(';')[0] : 'only ' + e.scenarios.join(', ') + ' left');
    case 'violation':
      // the forecast's property's value in the tile's terms; another property's in its own words
      return where + 'VIOLATION of ' + e.property + ': '
        + (missing(e.value) || e.property !== t.propertyId ? e.what || '' : pct(e.value, thr));
    case 'no-match':
      return where + 'no learned scenario matches this run any more';
    case 'run':
      return where + 'run ' + e.run + ' begins: every model starts over';
    case 'restarted':
      return (e.reason === 'reconnected' ? 'the connection to the robot was lost and made again'
        : 'the log was ' + e.reason) + ': monitoring starts over';
    case 'recovered':
      // an alarm its run took with it: nothing recovered, the run is over
      return where + (e.cause === 'run-ended' ? 'ALARM ENDS WITH ITS RUN'
        : 'RECOVERED' + (e.property && e.cause === 'discharged' ? ' (' + e.property + ')' : '')) + ': ' + e.reason;
    case 'under-way':
      return where + (e.underWay ? 'the action is under way (' : 'the action is no longer under way (') + e.by + ')';
    default:
      return where + e.event;
  }
}

/** This run's moments: "warned t=27.91 s (32.10%)". */
export function momentText(m, t) {
  const words = {warning: 'warned', violation: 'violated', recovered: 'recovered', 'violated again': 'violated again'};
  return (words[m.what] || m.what) + ' ' + at(m.time, t.unit) + ' (' + pct(m.value, t.threshold) + ')';
}

/**
 * An earlier run in one line, worst first: the other properties it violated, then the forecast property's own
 * ({@code ownId}) warning, violation and lead.
 */
export function earlierText(r, unit, ownId) {
  const others = (r.violated || []).filter(id => id !== ownId);
  return 'run ' + r.run + ' (line ' + r.line + '): ' + (others.length ? others.join(', ') + ' violated; '
    + (ownId ? ownId + ' ' : '') : '') + (r.warning ? 'warned' : 'no warning') + ', '
    + (r.violation ? 'violated' + (r.recovered ? ', then held again' : '') : 'held')
    + (r.lead !== null ? ', lead ' + span(r.lead, unit) : '') + (r.noMatch ? ', no model matched' : '');
}

/**
 * A property's forecast in a few words, or that it has none: "P(miss) 12%, 40 ticks left". The forecast's property
 * below the warning threshold says how far it is from a warning, with no countdown to a violation not expected.
 */
export function propertyForecast(p, t) {
  const f = p.forecast;
  if (p.model === 'forecast') {
    if (!f) return 'no forecast yet';
    if (p.skill === false) return 'no skill: the forecast did no better than the base rate';
    if (f.basis === 'violated') return 'violated: no forecast to make';
    const distance = t && isOwn(p, t) && own(t) !== 'warning' ? distanceWords(f, t.warnsAt) : null;
    if (distance) return distance;
    // not warned: no countdown to a violation its rule does not expect
    if (p.state !== 'warning' && !(t && isOwn(p, t))) return 'P ' + num(f.probability, 2) + ', no warning';
    return chance(f.probability) + ' chance of a violation, ' + whenWords(f);
  }
  if (!f) return p.forecastWords;
  const left = num(f.timeLeft, 0) + ' ' + f.unit + ' left';
  if (f.novel) return 'no forecast: pending longer than any training obligation; ' + left;
  if (p.skill === false) return 'no skill: the deadline forecast did no better than the base rate; ' + left;
  return 'P(miss) ' + chance(f.probability) + ', ' + left + (p.skill === true ? '' : ' \u00b7 skill not measured');
}
