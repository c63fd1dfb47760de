// Seeded random numbers for the Node tests and the Node benchmarks (bench/ imports this file:
// it holds no test code). Deterministic, so that a failure is reproducible by its seed.

/** mulberry32: each call gives the next unsigned 32-bit integer of the sequence of `seed`. */
export function mulberry32(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return (t ^ (t >>> 14)) >>> 0;
  };
}

/** Uniform numbers in [0, 1): mulberry32 / 2^32. */
export function uniform(seed) {
  const m = mulberry32(seed);
  return () => m() / 4294967296;
}

/** Standard Gaussian numbers: Box–Muller on the uniforms (mulberry32 + 0.5) / 2^32, in (0, 1). */
export function gauss(seed) {
  const m = mulberry32(seed);
  const u = () => (m() + 0.5) / 4294967296;
  return () => Math.sqrt(-2 * Math.log(u())) * Math.cos(2 * Math.PI * u());
}
