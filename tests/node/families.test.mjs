// The declarations methods() gives the page (it builds its controls from them, with no table of
// its own): the plant families under `families`, and each method parameter's `required` flag.
// Checked against what tune/simulate/analyze accept, on the wasm-pack nodejs build.
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab, SCENARIO, presetList } from './pidlab.mjs';

/** A small PI controller: proper for every family (an ideal derivative is ill-posed on a biproper one). */
const PI = { cr: { num: [0.1, 0.02], den: [1, 0] }, cy: { num: [0.1, 0.02], den: [1, 0] } };

const { methods, families } = pidlab.methods();

/** The family plant at the declared defaults. */
const defaults = (f) => Object.fromEntries([['family', f.id], ...f.params.map((p) => [p.name, p.default])]);

test('methods().families: one entry per family, each fully declared', () => {
  assert.ok(Array.isArray(families) && families.length > 0, 'methods() returns { methods, families }');
  const ids = families.map((f) => f.id);
  assert.equal(new Set(ids).size, ids.length, 'unique ids');
  for (const f of families) {
    for (const k of ['id', 'title', 'formula']) assert.ok(typeof f[k] === 'string' && f[k].length > 0, `${f.id}.${k}`);
    assert.ok(Number.isInteger(f.integrators) && f.integrators >= 0, `${f.id}.integrators`);
    assert.ok(Array.isArray(f.params) && f.params.length > 0, `${f.id}.params`);
    assert.equal(new Set(f.params.map((p) => p.name)).size, f.params.length, `${f.id}: unique parameter names`);
    for (const p of f.params) {
      for (const k of ['name', 'label', 'unit']) assert.ok(typeof p[k] === 'string' && p[k].length > 0, `${f.id}.${p.name}.${k}`);
      for (const k of ['default', 'min', 'max']) assert.ok(Number.isFinite(p[k]), `${f.id}.${p.name}.${k} is a number`);
      assert.ok(p.min <= p.default && p.default <= p.max, `${f.id}.${p.name}: min <= default <= max`);
    }
  }
  // Every family a method applies to is declared (num/den plants are "custom").
  for (const m of methods) for (const id of m.families) if (id !== 'custom') assert.ok(ids.includes(id), `${m.id}: family ${id} declared`);
});

test('every family plant built from the declared names and defaults is accepted; each name is one the crate requires', () => {
  for (const f of families) {
    const plant = defaults(f);
    const sim = pidlab.simulate({ plant, controller: PI, scenario: SCENARIO });
    assert.ok(sim.y.length > 1 && sim.t.length === sim.y.length, `${f.id}: simulated`);
    const an = pidlab.analyze({ plant, controller: PI });
    assert.equal(typeof an.stable, 'boolean', `${f.id}: analysed`);
    for (const p of f.params) {
      const less = { ...plant };
      delete less[p.name];
      for (const call of [() => pidlab.simulate({ plant: less, controller: PI, scenario: SCENARIO }), () => pidlab.analyze({ plant: less, controller: PI })]) {
        assert.throws(call, (e) => e.message.startsWith(`plant.${p.name}: `), `${f.id} without ${p.name}: an error naming plant.${p.name}`);
      }
    }
  }
});

test('the family a preset uses is declared with exactly the parameters the preset gives', () => {
  const byId = new Map(families.map((f) => [f.id, f]));
  let n = 0;
  for (const pr of presetList()) {
    for (const plant of [pr.plant, pr.tune && pr.tune.plant]) {
      if (!plant || typeof plant.family !== 'string') continue;
      const f = byId.get(plant.family);
      assert.ok(f, `${pr.id}: family ${plant.family} declared`);
      for (const p of f.params) assert.ok(Number.isFinite(plant[p.name]), `${pr.id}: ${plant.family}.${p.name} given`);
      n++;
    }
  }
  assert.ok(n > 0, 'some preset uses a family plant');
});

test("a parameter's `required` flag says whether the rule refuses to tune without it", (t) => {
  // From every preset that tunes: leave out, one at a time, each parameter without a default.
  // `required`: the rule refuses and names it; otherwise the rule chooses it (or fails for
  // another reason, never naming the omitted parameter as missing).
  const seen = { required: new Set(), chosen: new Set() };
  for (const pr of presetList()) {
    if (!pr.tune || !pr.tune.method || !pr.tune.params) continue;
    const m = methods.find((x) => x.id === pr.tune.method);
    assert.ok(m, `${pr.id}: method ${pr.tune.method} listed`);
    const plant = pr.tune.plant || pr.plant;
    for (const p of m.params) {
      assert.equal(typeof p.required, 'boolean', `${m.id}.${p.name}.required is declared`);
      if (p.default !== null || !(p.name in pr.tune.params)) continue;
      const params = { ...pr.tune.params };
      delete params[p.name];
      let msg = null;
      try {
        pidlab.tune({ method: m.id, plant, params });
      } catch (e) {
        msg = e.message;
      }
      const refused = msg !== null && msg.startsWith(`params.${p.name}`);
      assert.equal(refused, p.required, `${pr.id}: tune without ${p.name} ${refused ? 'refused' : 'accepted'}: ${msg}`);
      seen[p.required ? 'required' : 'chosen'].add(`${m.id}.${p.name}`);
    }
  }
  // The parameters no preset gives: on the method's first family at its declared defaults, with
  // λ solved for Ms 1.6 where the method offers that (λ is what the other parameters need).
  for (const m of methods) {
    const f = families.find((x) => x.id === m.families.find((id) => id !== 'custom'));
    if (!f) continue;
    const hasTarget = m.params.some((p) => p.name === 'target_ms');
    for (const p of m.params) {
      const key = `${m.id}.${p.name}`;
      if (p.default !== null || seen.required.has(key) || seen.chosen.has(key)) continue;
      const params = hasTarget && p.name !== 'lambda' && p.name !== 'target_ms' ? { target_ms: 1.6 } : {};
      let msg = null;
      try {
        pidlab.tune({ method: m.id, plant: defaults(f), params });
      } catch (e) {
        msg = e.message;
      }
      const refused = msg !== null && msg.startsWith(`params.${p.name}`);
      assert.equal(refused, p.required, `${key} on ${f.id} at its defaults: tune without it ${refused ? 'refused' : 'accepted'}: ${msg}`);
      seen[p.required ? 'required' : 'chosen'].add(key);
    }
  }
  assert.ok(seen.required.size > 0, 'some preset gives a required parameter');
  t.diagnostic(`required: ${[...seen.required].join(', ')}; chosen by the rule: ${[...seen.chosen].join(', ') || 'none given by a preset'}`);
});
