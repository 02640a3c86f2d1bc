// predmon live view: the property over the run, as SVG, with labelled ticks on both axes.
'use strict';
import {num, ownProperty, value} from './words.js';

const SVG = 'http://www.w3.org/2000/svg';

function svg(tag, attrs, text) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

/** Round steps (1, 2, 2.5, 5 times a power of ten) that cut [lo, hi] into about {@code count} parts. */
export function ticks(lo, hi, count) {
  const raw = (hi - lo) / Math.max(1, count);
  if (!(raw > 0) || !Number.isFinite(raw)) return [lo];
  const power = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 2.5, 5, 10].map(m => m * power).find(s => s >= raw);
  const out = [];
  for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) out.push(Number(v.toFixed(10)));
  return out;
}

/** Enough decimals to tell ticks {@code step} apart. */
const decimals = (step) => step >= 1 ? 0 : Math.min(3, Math.ceil(-Math.log10(step) - 1e-9));

/**
 * The plot of tile {@code t}: the forecast property's readings (named, one property among the others), its threshold,
 * its warning and its violation, and where any other property was violated.
 */
export function plot(t) {
  const W = 440, H = 178, L = 40, R = 12, T = 16, B = 34;
  const own = ownProperty(t);
  const others = (t.properties || []).filter(p => p !== own && p.state === 'violated' && typeof p.time === 'number');
  const s = svg('svg', {class: 'plot', viewBox: '0 0 ' + W + ' ' + H, role: 'img',
    'aria-label': (own ? own.property + ' (' + own.name + ')' : t.property || 'the property') + ' over time in run '
      + t.run + others.map(p => '; ' + p.property + ' violated ' + (t.unit === 'ticks' ? 'at tick ' : 'at t=')
      + num(p.time, 2)).join('')});
  s.appendChild(svg('rect', {class: 'frame', x: L, y: T, width: W - L - R, height: H - T - B}));
  if (own && (t.properties || []).length > 1) {
    s.appendChild(svg('text', {class: 'series-name', x: 2, y: H - 4}, own.property));
  }
  const pts = t.series;
  const times = pts.map(p => p[0]);
  if (t.warning) times.push(t.warning.time);
  if (t.violation) times.push(t.violation.time);
  for (const p of others) times.push(p.time);
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
  for (const g of ticks(lo, hi, 5)) {
    s.appendChild(svg('line', {class: 'grid', x1: L, x2: W - R, y1: y(g), y2: y(g)}));
    s.appendChild(svg('text', {class: 'axis', x: L - 5, y: y(g) + 3.5, 'text-anchor': 'end'}, String(g)));
  }
  const xs = ticks(t0, t1, 5);
  const xd = decimals(xs.length > 1 ? xs[1] - xs[0] : 1);
  for (const g of xs) {
    s.appendChild(svg('line', {class: 'grid', x1: x(g), x2: x(g), y1: T, y2: H - B}));
    s.appendChild(svg('line', {class: 'tick', x1: x(g), x2: x(g), y1: H - B, y2: H - B + 4}));
    s.appendChild(svg('text', {class: 'axis', x: x(g), y: H - B + 14, 'text-anchor': 'middle'}, num(g, xd)));
  }
  s.appendChild(svg('text', {class: 'axis-title', x: (L + W - R) / 2, y: H - 4, 'text-anchor': 'middle'},
    t.unit === 'ticks' ? 'tick of the tree' : 'time in the log (s)'));
  if (t.threshold !== undefined && t.threshold !== null) {
    s.appendChild(svg('line', {class: 'threshold', x1: L, x2: W - R, y1: y(t.threshold), y2: y(t.threshold)}));
    // At the left, where the run begins high above it; the warning and the violation come at the right.
    s.appendChild(svg('text', {class: 'label-threshold', x: L + 3, y: y(t.threshold) - 3}, 'limit ' + value(t.threshold)));
  }
  if (pts.length > 0) {
    s.appendChild(svg('polyline', {class: 'series',
      points: pts.map(p => x(p[0]).toFixed(1) + ',' + y(p[1]).toFixed(1)).join(' ')}));
  }
  const mark = (time, kind, label, anchorRight, y0) => {
    const right = anchorRight || x(time) > W - R - 50; // a label that would leave the plot goes left of its line
    s.appendChild(svg('line', {class: 'mark-' + kind, x1: x(time), x2: x(time), y1: T, y2: H - B}));
    s.appendChild(svg('text', {class: 'label-' + kind, x: x(time) + (right ? -3 : 3), y: y0,
      'text-anchor': right ? 'end' : 'start'}, label));
  };
  const name = own && others.length > 0 ? own.property + ' ' : '';
  if (t.warning) mark(t.warning.time, 'warning', name + 'warning', !!t.violation, T - 4);
  if (t.violation) {
    // Close to the warning's mark, its label goes one line lower so that the two do not overlap.
    const close = t.warning && Math.abs(x(t.violation.time) - x(t.warning.time)) < 60;
    mark(t.violation.time, 'violation', name + 'violation', false, close ? T + 10 : T - 4);
  }
  // every other property's violation, its id on its line, each a line lower than the one before and below the
  // forecast property's own labels
  const below = t.warning || t.violation ? T + 22 : T + 10;
  others.forEach((p, i) => mark(p.time, 'violation', p.property + ' violated', false, below + 12 * i));
  return s;
}
