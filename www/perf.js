// The page's own timing of each render (read by the browser test and bench/page-latency.mjs
// through window.__pidlab.perf): performance.now() laps per stage; a stage that did not run is
// absent.

export const perf = { renders: 0, lastWorkMs: 0, works: [], phases: {} };

/** Adds the time since `t0` to stage `name`; returns now (the next stage's start). */
export const lap = (name, t0) => {
  const t = performance.now();
  perf.phases[name] = (perf.phases[name] || 0) + t - t0;
  return t;
};
