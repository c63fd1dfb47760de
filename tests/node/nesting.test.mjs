// Cyclic and very deeply nested inputs (API.md: no input may trap the module). Kept in its own
// file, so its own process and its own wasm instance: a stack overflow while reading the input
// corrupts the instance, and that must not hide behind the other tests' results.
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab, BOILER, IPD, FIELD_PATH } from './pidlab.mjs';

const SCEN = { t_end: 5, dt: 0.01, setpoint: { time: 0, size: 1 }, disturbance: { time: 2.5, size: 1 } };

function deep(depth) {
  let v = [1];
  for (let i = 0; i < depth; i++) v = i % 2 ? [v] : { a: v };
  return v;
}

function inputs() {
  const cyclicPlant = { num: [1], den: [1, 1], delay: 0 };
  cyclicPlant.self = cyclicPlant;
  const cyclicArray = [1, 2];
  cyclicArray.push(cyclicArray);
  return [
    ['cyclic plant', { method: 'praveen_kumar', plant: cyclicPlant, controller: IPD, scenario: SCEN, params: { lambda: 1.9 } }],
    ['cyclic array in a polynomial', { plant: { num: cyclicArray, den: [1, 1], delay: 0 }, controller: IPD, scenario: SCEN }],
    ['nested 10⁴ deep', { plant: BOILER, controller: IPD, scenario: SCEN, extra: deep(10000) }],
    ['nested 10⁵ deep', { plant: deep(100000), controller: IPD, scenario: SCEN }],
  ];
}

test('cyclic and deeply nested inputs are refused with a field-path Error, without trapping', () => {
  const failures = [];
  for (const name of ['tune', 'simulate', 'analyze', 'reduce'].filter((n) => typeof pidlab[n] === 'function')) {
    for (const [what, input] of inputs()) {
      try {
        pidlab[name](input);
      } catch (e) {
        const msg = e instanceof Error ? e.message : `non-Error ${String(e)}`;
        if (!(e instanceof Error) || !FIELD_PATH.test(msg)) failures.push(`${name}(${what}): ${msg}`);
      }
    }
  }
  assert.equal(failures.length, 0, failures.join('\n'));
});

test('the module still works afterwards', () => {
  const a = pidlab.analyze({ plant: BOILER, controller: IPD });
  assert.equal(a.stable, true);
  assert.ok(Math.abs(a.ms - 1.6754) < 1e-3, `Ms ${a.ms}`);
  const s = pidlab.simulate({ plant: BOILER, controller: IPD, scenario: SCEN });
  assert.equal(s.y.length, 501);
  for (let i = 0; i < 100; i++) pidlab.analyze({ plant: BOILER, controller: IPD });
});
