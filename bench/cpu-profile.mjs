// Shared by the page benchmarks that read a CPU profile (bench/page-cpu.mjs, bench/drag-trace.mjs):
// the profile's samples summed per JS function, inclusive (a function counted once per sample
// however deep it recurs), for the samples whose time `inWindow(t)` accepts. Times in µs, as
// the profile's own (`Profiler.stop`'s startTime, samples, timeDeltas).

/** `{ byId, parent }`: the profile's nodes by id and each node's parent id. */
export function profileTree(profile) {
  const byId = new Map(profile.nodes.map((nd) => [nd.id, nd]));
  const parent = new Map();
  for (const nd of profile.nodes) for (const ch of nd.children || []) parent.set(ch, nd.id);
  return { byId, parent };
}

/** Inclusive µs per function name over the samples inside the window. */
export function inclusiveByFunction(profile, inWindow) {
  const { byId, parent } = profileTree(profile);
  const incl = new Map();
  let t = profile.startTime;
  for (let k = 0; k < profile.samples.length; k++) {
    t += profile.timeDeltas[k];
    if (!inWindow(t)) continue;
    const us = profile.timeDeltas[k + 1] || 0;
    const seen = new Set();
    for (let x = profile.samples[k]; x !== undefined; x = parent.get(x)) {
      const fr = byId.get(x).callFrame;
      if (!fr.functionName || seen.has(fr.functionName)) continue;
      seen.add(fr.functionName);
      incl.set(fr.functionName, (incl.get(fr.functionName) || 0) + us);
    }
  }
  return incl;
}
