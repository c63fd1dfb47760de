// admissible({ method, plant, params? }) on the wasm-pack nodejs build: the JSON shape the page
// builds its sliders from, the suggested values give a design tune/analyze accept, and bad input
// gets errors that begin with the field's path.
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab } from './pidlab.mjs';

const { methods, families } = pidlab.methods();
const defaults = (f) => Object.fromEntries([['family', f.id], ...f.params.map((p) => [p.name, p.default])]);
const ENDS = ['declared', 'fails', 'unstable', 'ms_high', 'ms_low', 'sluggish', 'achievable'];

test('admissible: every continuous parameter of every method on each family it claims', () => {
  for (const f of families) {
    const plant = defaults(f);
    for (const m of methods.filter((m) => m.families.includes(f.id) && m.id !== 'arvanitis_alg3')) {
      const r = pidlab.admissible({ method: m.id, plant });
      assert.equal(r.method, m.id);
      const continuous = m.params.filter((p) => p.min !== null && !p.choices && !p.values).map((p) => p.name);
      for (const name of Object.keys(r.params)) assert.ok(continuous.includes(name), `${m.id}: ${name} is continuous`);
      const params = {};
      for (const [name, iv] of Object.entries(r.params)) {
        for (const k of ['min', 'max', 'suggested']) assert.ok(Number.isFinite(iv[k]), `${m.id}.${name}.${k}`);
        assert.ok(iv.min <= iv.suggested && iv.suggested <= iv.max, `${m.id}.${name}: min <= suggested <= max`);
        assert.ok(ENDS.includes(iv.min_end) && ENDS.includes(iv.max_end), `${m.id}.${name}: ends`);
        assert.equal(iv.min_open, ['fails', 'unstable'].includes(iv.min_end));
        assert.ok(['linear', 'log'].includes(iv.scale));
        assert.ok(typeof iv.note === 'string' && iv.note.length > 0);
        if (!['target_ms', 'fit_ms'].includes(name)) params[name] = iv.suggested;
      }
      const t = pidlab.tune({ method: m.id, plant, params });
      const a = pidlab.analyze({ plant, controller: t.controller });
      assert.equal(a.stable, true, `${f.id} × ${m.id} at the suggestions`);
    }
  }
});

test('admissible: discrete and choice parameters are not intervals; p_order is [2, 3]', () => {
  const med = methods.find((m) => m.id === 'medarametla');
  assert.deepEqual(med.params.find((p) => p.name === 'p_order').values, [2, 3]);
  const r = pidlab.admissible({ method: 'medarametla', plant: { family: 'piptd', k: 1, theta: 0.5 } });
  assert.ok(!('p_order' in r.params));
  assert.ok('lambda' in r.params);
});

test('admissible: bad input names the field', () => {
  const plant = { family: 'piptd', k: 1, theta: 0.5 };
  const err = (input) => {
    try {
      pidlab.admissible(input);
    } catch (e) {
      return String(e.message ?? e);
    }
    assert.fail('no error');
  };
  assert.match(err({ method: 'shamsuzzoha_le', plant }), /^method: unknown method 'shamsuzzoha_le' \(did you mean 'shamsuzzoha_lee'\?\)/);
  assert.match(err({ method: 'kaya', plant }), /^plant\.family: method 'kaya' applies to families/);
  assert.match(err({ method: 'shamsuzzoha_lee', plant, params: { lamda: 1 } }), /^params\.lamda: unknown field/);
  assert.match(err({ method: 'shamsuzzoha_lee', plant, extra: 1 }), /^extra: unknown field/);
  assert.match(err({ method: 'shamsuzzoha_lee', plant, params: { gamma: 1e308 } }), /^params\.gamma: must lie in \[0, 1\] \(got 1e308\)/);
});

test('Algorithm III: details count Parseval evaluations; a scan refused for one reason says it', () => {
  const plant = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
  const t = pidlab.tune({ method: 'arvanitis_alg3', plant, params: { zeta: 0.6 } });
  // the boiler's design is taken by Parseval alone: no simulation, a few evaluations
  assert.equal(t.details.simulations, 0);
  assert.ok(Number.isInteger(t.details.evaluations) && t.details.evaluations > 0, String(t.details.evaluations));
  assert.throws(
    () => pidlab.admissible({ method: 'arvanitis_alg3', plant, params: { criterion: 'isensdco' } }),
    (e) => e.message.startsWith('params.zeta: no value of ') && e.message.includes('the rule refuses every one (params.criterion: ISENSDCO'),
  );
});
