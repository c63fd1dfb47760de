// The mapping of a slider's positions to parameter values (www/controls.js), checked in Node:
// every position, Home and End included, is inside the interval, strictly inside an open end;
// values increase with the position; a value maps back to its own position.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { POSITIONS, valueAt, positionOf } from '../../www/controls.js';

const intervals = [
  // Praveen Kumar's λ on the boiler (the rule's own message: admissible λ ∈ (0.203703, 1.973089))
  { min: 0.203703, max: 1.973089, minOpen: true, maxOpen: true, log: false },
  // a range over 12 decades, open at 0-like lower end
  { min: 1e-6, max: 1e6, minOpen: true, maxOpen: false, log: true },
  // a narrow interval far from 0 (rounding must not reach the open end)
  { min: 100, max: 100.5, minOpen: true, maxOpen: true, log: false },
  // closed, crossing zero
  { min: -50, max: 50, minOpen: false, maxOpen: false, log: false },
];

test('every slider position is an admissible value; Home and End land inside open ends', () => {
  assert.ok(POSITIONS >= 100);
  for (const r of intervals) {
    let prev = -Infinity;
    for (let p = 0; p <= POSITIONS; p++) {
      const v = valueAt(r, p);
      assert.ok(r.minOpen ? v > r.min : v >= r.min, `${JSON.stringify(r)} position ${p}: ${v}`);
      assert.ok(r.maxOpen ? v < r.max : v <= r.max, `${JSON.stringify(r)} position ${p}: ${v}`);
      assert.ok(v > prev, `increasing at ${p}: ${v} after ${prev}`);
      prev = v;
      assert.equal(positionOf(r, v), p, `${v} maps back to position ${p}`);
    }
    // a closed end is reached exactly
    if (!r.minOpen) assert.equal(valueAt(r, 0), r.min);
    if (!r.maxOpen) assert.equal(valueAt(r, POSITIONS), r.max);
    // an open end is approached to 1/POSITIONS of the span (log span on a log scale)
    if (r.minOpen && !r.log) assert.ok(valueAt(r, 0) - r.min <= 1.1 * (r.max - r.min) / POSITIONS);
  }
});

test('values are written short: at most a tenth of a step of rounding', () => {
  const r = intervals[0];
  const v = valueAt(r, 437);
  assert.ok(String(v).length <= 8, String(v));
  const step = (r.max - r.min) / POSITIONS;
  const exact = r.min + step + (437 / POSITIONS) * (r.max - r.min - 2 * step);
  assert.ok(Math.abs(v - exact) <= step / 10, `${v} vs ${exact}`);
});
