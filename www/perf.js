// The page's own timing of each render (read by the browser test and bench/page-latency.mjs
// through window.__pidlab.perf): performance.now() laps per stage; a stage that did not run is
// absent.

// inputs: renders for a new input so far; shown: the `inputs` count whose results are on screen
// (equal when the page shows its latest input).
// startup: performance.now() at the app's start (script), the first module compiled
// (compiled), methods() and presets() read (methods), the controls built (controls: with the
// method panel's λ for Ms = 1.6, computed on this thread at start-up), everything wired (built);
// firstPlotsAt: when the first response plots were drawn (bench/page-latency.mjs --first), and
// firstPhases: that render's phases; firstTablesMs: its metrics table and controller section,
// drawn in the task after its frame (app.js render());
// classroom: the time of each later chunk that draws a classroom panel (app.js), the last 1000;
// secondary: the same for the task after a later result's frame that draws its control signal
// and Nyquist plots and its metrics table (app.js scheduleSecondary).
export const perf = { renders: 0, lastWorkMs: 0, works: [], phases: {}, inputs: 0, shown: 0, startup: {}, firstPlotsAt: 0, firstPhases: null, firstTablesMs: 0, classroom: [], secondary: [] };

/** Adds the time since `t0` to stage `name`; returns now (the next stage's start). */
export const lap = (name, t0) => {
  const t = performance.now();
  perf.phases[name] = (perf.phases[name] || 0) + t - t0;
  return t;
};
